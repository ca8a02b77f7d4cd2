// The minimal sphere enclosing a point set (Welzl's algorithm, in its incremental form),
// the reference centre of the thesis' vertex pursuit (3.1).
#pragma once

#include "geometry/point_cloud.hpp"

namespace cloudshape::geometry {

struct Sphere {
  Point center = Point::Zero();
  double radius = 0.0;
};

// Exact minimal enclosing sphere. Expected linear time: the points are visited in
// a fixed pseudo-random order, so the result is deterministic.
Sphere minimal_enclosing_sphere(const PointList& points);

}  // namespace cloudshape::geometry
