#include "render/cameras.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/pca.hpp"

namespace cloudshape::render {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

Eigen::Matrix3d frame(const Eigen::Vector3d& right, const Eigen::Vector3d& down,
                      const Eigen::Vector3d& forward) {
  Eigen::Matrix3d r;
  r.row(0) = right.transpose();
  r.row(1) = down.transpose();
  r.row(2) = forward.transpose();
  return r;
}

}  // namespace

Camera sensor_camera() { return Camera{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), true}; }

Camera principal_axes_camera(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& viewer_side) {
  const geometry::Pca pca = geometry::compute_pca(points);
  Eigen::Vector3d forward = pca.eigenvectors.col(0);
  Eigen::Vector3d right = pca.eigenvectors.col(2);
  if (forward.dot(pca.centroid - viewer_side) < 0.0) forward = -forward;
  Eigen::Vector3d down = forward.cross(right);
  // Like a depth camera's y, down leans towards +y where it can (a half-turn keeps it a rotation).
  if (down.y() < 0.0) {
    down = -down;
    right = -right;
  }
  return Camera{frame(right, down, forward), pca.centroid, false};
}

Camera oblique_camera(const Camera& base, const Eigen::Vector3d& pivot, double azimuth_deg,
                      double elevation_deg) {
  const Eigen::Vector3d right = base.rotation.row(0).transpose();
  const Eigen::Vector3d down = base.rotation.row(1).transpose();
  const Eigen::Vector3d forward = base.rotation.row(2).transpose();
  const double az = azimuth_deg * kDegree, el = elevation_deg * kDegree;
  // Moving the camera right and up about the pivot turns its line of sight left and down.
  const Eigen::Vector3d turned = std::cos(az) * forward - std::sin(az) * right;
  const Eigen::Vector3d f = (std::cos(el) * turned + std::sin(el) * down).normalized();
  const Eigen::Vector3d d = (down - down.dot(f) * f).normalized();
  return Camera{frame(d.cross(f), d, f), pivot, false};
}

}  // namespace cloudshape::render
