#include "pipeline/free_space.hpp"

#include <algorithm>
#include <cmath>

namespace cloudshape::pipeline {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

}  // namespace

RaysThroughSolid rays_through_solid(const PointList& returns, const Point& sensor,
                                    const std::function<double(const Point&)>& signed_distance,
                                    const Point& centre, double reach, double depth) {
  RaysThroughSolid out;
  const Eigen::Vector3d to_centre = centre - sensor;
  const double centre_range = to_centre.norm();
  if (!signed_distance || !(reach > 0.0) || !(depth > 0.0) || !(centre_range > 0.0)) return out;
  // A sensor inside the reach may see the solid in any direction.
  const double min_cos = reach >= centre_range
                             ? -1.0
                             : std::sqrt(1.0 - (reach / centre_range) * (reach / centre_range));
  const double begin = std::max(0.0, centre_range - reach), end = centre_range + reach;
  // The march steps at least this far: a ray inside by more than `depth` stays inside over about
  // that length unless it grazes the surface.
  const double min_step = 0.5 * depth;
  for (const Point& q : returns) {
    const Eigen::Vector3d ray = q - sensor;
    const double range = ray.norm();
    if (!(range > 0.0)) continue;
    const Eigen::Vector3d u = ray / range;
    if (u.dot(to_centre) < min_cos * centre_range) continue;
    for (double s = begin; s <= end;) {
      const double d = signed_distance(sensor + s * u);
      if (d < -depth) {
        ++out.crossing;
        if (s < range - depth) ++out.through;
        break;
      }
      s += std::max(d, min_step);
    }
  }
  return out;
}

PointList returns_about(const PointList& frame, const PointList& points, const Point& sensor,
                        double factor) {
  PointList out;
  if (points.empty()) return out;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Point& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  const Eigen::Vector3d axis = (centroid - sensor).normalized();
  if (!axis.allFinite()) return out;
  double min_cos = 1.0;
  for (const Point& p : points) {
    const Eigen::Vector3d d = (p - sensor).normalized();
    if (d.allFinite()) min_cos = std::min(min_cos, d.dot(axis));
  }
  const double widest = std::acos(std::clamp(min_cos, -1.0, 1.0));
  const double limit = std::cos(std::min(kHalfPi, factor * widest));
  // Within the angle: d.axis >= limit |d|, both sides non-negative, so squared (no root per
  // return).
  const double limit_squared = limit * limit;
  for (const Point& q : frame) {
    const Eigen::Vector3d d = q - sensor;
    const double along = d.dot(axis);
    if (along > 0.0 && along * along >= limit_squared * d.squaredNorm()) out.push_back(q);
  }
  return out;
}

}  // namespace cloudshape::pipeline
