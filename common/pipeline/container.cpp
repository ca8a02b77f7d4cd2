#include "pipeline/container.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/pca.hpp"

namespace cloudshape::pipeline {

bool seen_from_inside(const PointList& cloud, const FittedSolid& solid, const Point& viewpoint, double step,
                      const config::SolveConfig& cfg) {
  const bool round = solid.shape == Shape::sphere || solid.shape == Shape::cone || solid.shape == Shape::frustum;
  if (cloud.empty() || !round || !solid.signed_distance || !(step > 0.0)) return false;
  // A sensor looks into a hollow from outside the solid it belongs to (over a bowl's rim).
  if (solid.signed_distance(viewpoint) <= 0.0) return false;
  const std::size_t stride = std::max<std::size_t>(1, cloud.size() / std::max<std::int64_t>(1, cfg.verify_samples));
  std::size_t away = 0, seen = 0;
  for (std::size_t i = 0; i < cloud.size(); i += stride, ++seen) {
    const Point& p = cloud[i];
    Eigen::Vector3d gradient;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = step * Eigen::Vector3d::Unit(k);
      gradient[k] = solid.signed_distance(p + e) - solid.signed_distance(p - e);
    }
    if (gradient.dot(viewpoint - p) < 0.0) ++away;
  }
  return static_cast<double>(away) > cfg.inside_view_share * static_cast<double>(seen);
}

std::optional<FittedSolid> container_of_hollow(const PointList& cloud, const FittedSolid& hollow,
                                               const config::SolveConfig& cfg) {
  if (cloud.size() < 4 || !hollow.signed_distance) return std::nullopt;
  // A sphere has no axis of its own: the hollow of a bowl is wider than deep, so its thinnest
  // direction is the axis (the way from its centre to the points' centroid leans towards the side seen).
  Eigen::Vector3d axis = hollow.axes.row(0).transpose();
  if (hollow.shape == Shape::sphere) axis = geometry::compute_pca(cloud).eigenvectors.col(0).normalized();
  std::vector<double> radial, along;
  radial.reserve(cloud.size());
  along.reserve(cloud.size());
  for (const Point& p : cloud) {
    const Eigen::Vector3d d = p - hollow.center;
    along.push_back(d.dot(axis));
    radial.push_back((d - along.back() * axis).norm());
  }
  const auto quantile = [](std::vector<double>& v, double q) {
    const auto k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
  };
  const double q = cfg.container_rim_quantile;
  const double radius = quantile(radial, q);
  const double lo = quantile(along, 1.0 - q), hi = quantile(along, q);
  if (!(radius > 0.0) || !(hi > lo)) return std::nullopt;
  FittedSolid out;
  out.shape = Shape::cylinder;
  out.dimensions = {{"radius", radius}, {"height", hi - lo}};
  out.center = hollow.center + 0.5 * (lo + hi) * axis;
  out.axes = detail::frame_from_axis(axis);
  const Point c = out.center;
  const double height = hi - lo;
  out.signed_distance = [c, axis, radius, height, inside = hollow.signed_distance](const Point& p) {
    const Eigen::Vector3d d = p - c;
    const double h = d.dot(axis);
    const double wall = std::max((d - h * axis).norm() - radius, std::abs(h) - 0.5 * height);
    if (wall >= 0.0) return wall;
    return std::max(wall, -std::abs(inside(p)));
  };
  return out;
}

}  // namespace cloudshape::pipeline
