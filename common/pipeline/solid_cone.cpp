#include <Eigen/Dense>
#include <cmath>

#include "geometry/circle.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

std::optional<FittedSolid> fit_cone(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  if (faces.empty()) return std::nullopt;
  const DetectedPlane& base = *faces[0];
  // The base's normal points away from the cloud, the apex lies the other way.
  const Eigen::Vector3d axis = -base.plane.normal;

  Point base_centroid = Point::Zero();
  for (std::uint32_t i : base.inliers) base_centroid += in.cloud[i];
  base_centroid /= static_cast<double>(base.inliers.size());
  const auto& rim = base.boundary.size() >= 6 ? base.boundary : base.inliers;
  const auto circle = geometry::fit_circle_in_plane(in.cloud, rim, base_centroid, axis);
  const Point centre = circle ? circle->center : base_centroid;

  // Along the side, the distance to the axis falls linearly with the height above the
  // base: r = R - (R/H) h. A regression over every side point gives R and H.
  const auto side = detail::points_off_faces(in.cloud, {&base});
  if (side.size() < 10) return std::nullopt;
  double h_max = 0.0;
  for (std::uint32_t i : side) h_max = std::max(h_max, (in.cloud[i] - centre).dot(axis));
  if (!(h_max > 0.0)) return std::nullopt;
  Eigen::Matrix2d ata = Eigen::Matrix2d::Zero();
  Eigen::Vector2d atb = Eigen::Vector2d::Zero();
  for (std::uint32_t i : side) {
    const Eigen::Vector3d d = in.cloud[i] - centre;
    const double h = d.dot(axis);
    if (h < 0.05 * h_max || h > 0.95 * h_max) continue;
    const double r = (d - h * axis).norm();
    const Eigen::Vector2d row(1.0, -h);
    ata.noalias() += row * row.transpose();
    atb.noalias() += row * r;
  }
  const Eigen::Vector2d sol = ata.ldlt().solve(atb);
  const double radius = sol(0), slope = sol(1);
  if (!(radius > 0.0) || !(slope > 0.0) || !sol.allFinite()) return std::nullopt;
  const double height = radius / slope;

  FittedSolid out;
  out.shape = Shape::cone;
  out.dimensions = {{"radius", radius}, {"height", height}};
  out.center = centre;
  out.axes = detail::frame_from_axis(axis);
  const double slant = std::hypot(radius, height);
  out.signed_distance = [centre, axis, radius, height, slant](const Point& p) {
    const Eigen::Vector3d d = p - centre;
    const double h = d.dot(axis);
    const double r = (d - h * axis).norm();
    return std::max(-h, (r * height + h * radius - radius * height) / slant);
  };
  return out;
}

}  // namespace cloudshape::pipeline
