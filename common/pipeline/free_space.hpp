// Whether a sensor saw through a solid: of the rays it cast that cross the solid, those whose
// return lies beyond it. A solid standing where the sensor measured free space is not there.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::pipeline {

struct RaysThroughSolid {
  // Rays running deeper than the depth inside the solid.
  std::size_t crossing = 0;
  // Of those, rays that return more than the depth beyond where they enter it.
  std::size_t through = 0;
};

// The rays from `sensor` to each of `returns` whose direction comes within the solid's reach (a
// ball of radius `reach` about `centre` holding it), each marched along the solid's
// `signed_distance` (negative inside; exact on the surface, a lower bound away from it) from where
// it meets that ball. Grazing rays that stay within `depth` of the surface count for neither.
RaysThroughSolid rays_through_solid(const PointList& returns, const Point& sensor,
                                    const std::function<double(const Point&)>& signed_distance,
                                    const Point& centre, double reach, double depth);

// The returns about an object (its own included): those within `factor` times the widest angle
// between `points` and their centroid, seen from `sensor` (at most a half-space).
PointList returns_about(const PointList& frame, const PointList& points, const Point& sensor,
                        double factor);

}  // namespace cloudshape::pipeline
