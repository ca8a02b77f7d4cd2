#include "pipeline/container.hpp"

#include <algorithm>
#include <cmath>

namespace cloudshape::pipeline {

bool seen_from_inside(const PointList& cloud, const FittedSolid& sphere, const Point& viewpoint,
                      const config::SolveConfig& cfg) {
  if (cloud.empty() || sphere.shape != Shape::sphere) return false;
  std::size_t away = 0;
  for (const Point& p : cloud)
    if ((p - sphere.center).dot(viewpoint - p) < 0.0) ++away;
  return static_cast<double>(away) > cfg.inside_view_share * static_cast<double>(cloud.size());
}

std::optional<FittedSolid> container_of_hollow(const PointList& cloud, const FittedSolid& sphere,
                                               const config::SolveConfig& cfg) {
  if (cloud.size() < 4 || sphere.dimensions.empty()) return std::nullopt;
  Point centroid = Point::Zero();
  for (const Point& p : cloud) centroid += p;
  centroid /= static_cast<double>(cloud.size());
  const Eigen::Vector3d towards_floor = centroid - sphere.center;
  if (!(towards_floor.norm() > 0.0)) return std::nullopt;
  const Eigen::Vector3d axis = towards_floor.normalized();
  std::vector<double> radial, along;
  radial.reserve(cloud.size());
  along.reserve(cloud.size());
  for (const Point& p : cloud) {
    const Eigen::Vector3d d = p - sphere.center;
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
  out.center = sphere.center + 0.5 * (lo + hi) * axis;
  out.axes = detail::frame_from_axis(axis);
  const Point c = out.center, hollow = sphere.center;
  const double height = hi - lo, hollow_radius = sphere.dimensions.front().second;
  out.signed_distance = [c, axis, radius, height, hollow, hollow_radius](const Point& p) {
    const Eigen::Vector3d d = p - c;
    const double h = d.dot(axis);
    const double wall = std::max((d - h * axis).norm() - radius, std::abs(h) - 0.5 * height);
    if (wall >= 0.0) return wall;
    return std::max(wall, -std::abs((p - hollow).norm() - hollow_radius));
  };
  return out;
}

}  // namespace cloudshape::pipeline
