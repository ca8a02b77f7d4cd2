#include "geometry/plane.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "geometry/pca.hpp"

namespace cloudshape::geometry {

std::optional<Plane> plane_through(const Point& a, const Point& b, const Point& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double len = n.norm();
  const double scale = (b - a).squaredNorm() + (c - a).squaredNorm();
  if (!(len > 1e-12 * scale) || len == 0.0) return std::nullopt;
  Plane p;
  p.normal = n / len;
  p.offset = -p.normal.dot(a);
  return p;
}

Plane fit_plane_least_squares(const PointList& points, const std::vector<std::uint32_t>& indices) {
  const Pca pca = compute_pca(points, indices);
  Plane p;
  p.normal = pca.eigenvectors.col(0).normalized();
  p.offset = -p.normal.dot(pca.centroid);
  return p;
}

std::optional<Line> intersect_planes(const Plane& a, const Plane& b, double min_sin_angle) {
  const Eigen::Vector3d dir = a.normal.cross(b.normal);
  const double s = dir.norm();
  if (s < min_sin_angle) return std::nullopt;
  Line line;
  line.direction = dir / s;
  // The point on the line nearest the origin solves the two plane equations plus
  // dir.x = 0; a 3x3 system that is well conditioned once the planes are not parallel.
  Eigen::Matrix3d m;
  m.row(0) = a.normal.transpose();
  m.row(1) = b.normal.transpose();
  m.row(2) = line.direction.transpose();
  line.point = m.colPivHouseholderQr().solve(Eigen::Vector3d(-a.offset, -b.offset, 0.0));
  return line;
}

std::optional<Point> intersect_three_planes(const Plane& a, const Plane& b, const Plane& c) {
  Eigen::Matrix3d m;
  m.row(0) = a.normal.transpose();
  m.row(1) = b.normal.transpose();
  m.row(2) = c.normal.transpose();
  if (std::abs(m.determinant()) < 1e-6) return std::nullopt;
  return Point(m.partialPivLu().solve(Eigen::Vector3d(-a.offset, -b.offset, -c.offset)));
}

void plane_basis(const Eigen::Vector3d& normal, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  const Eigen::Vector3d n = normal.normalized();
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  u = n.cross(helper).normalized();
  v = n.cross(u);
}

}  // namespace cloudshape::geometry
