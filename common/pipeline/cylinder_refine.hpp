// A cylinder's axis, axis point and radius refined together on its side points: a robust
// Gauss-Newton fit of the point-to-side distance, for sides whose axis came from normals alone.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::pipeline::detail {

struct SideCylinder {
  Point on_axis = Point::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit
  double radius = 0.0;
};

// Refines `start` on the indexed points. Each step weighs a point by Tukey's biweight of its
// distance from the side with scale `band` (points farther count nothing: caps, rims, clutter),
// so a start within about `band` of the side converges to it. Returns `start` when too few points
// are near it or the steps do not settle.
SideCylinder refine_side_cylinder(const PointList& cloud, const std::vector<std::uint32_t>& side,
                                  const SideCylinder& start, double band, int iterations);

// A cone's side (a frustum's): the distance from the axis r0 + slope * h at height h along `axis`
// from `on_axis`.
struct SideCone {
  Point on_axis = Point::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit
  double radius = 0.0;                              // at on_axis
  double slope = 0.0;
};

// The same fit with the slope free: `start` (a cylinder's, slope 0) refined first with a band of
// `loose_band` (a taper's ends lie far off a cylinder), then of `band`. Returns nothing when too
// few points are near it or a step fails.
std::optional<SideCone> refine_side_cone(const PointList& cloud,
                                         const std::vector<std::uint32_t>& side,
                                         const SideCone& start, double loose_band, double band,
                                         int iterations);

// Degrees of arc around `c`'s axis the indexed points within `band` of its side cover, in 10
// degree sectors each holding at least 1% of them: a side seen over a narrow arc (a flat face
// tangent to the cylinder) is no evidence of a curved one.
double side_arc_degrees(const PointList& cloud, const std::vector<std::uint32_t>& side,
                        const SideCylinder& c, double band);
// A point's distance from a cone's side (outside positive).
double side_distance(const SideCone& c, const Point& p);

// The same around a cone's side.
double side_arc_degrees(const PointList& cloud, const std::vector<std::uint32_t>& side, const SideCone& c,
                        double band);

}  // namespace cloudshape::pipeline::detail
