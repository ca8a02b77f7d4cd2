// The minimal sphere enclosing a point set (Welzl's algorithm, in its incremental form),
// the reference centre of the thesis' vertex pursuit (3.1).
#pragma once

#include <cstddef>

#include "geometry/point_cloud.hpp"

namespace cloudshape::geometry {

struct Sphere {
  Point center = Point::Zero();
  double radius = 0.0;
};

// Exact minimal enclosing sphere. Expected linear time: the points are visited in
// a fixed pseudo-random order, so the result is deterministic.
Sphere minimal_enclosing_sphere(const PointList& points);

namespace detail {

// Whether p lies outside s, beyond a relative 1e-10 and an absolute 1e-12 (the loops' test).
bool outside(const Sphere& s, const Point& p);

// The first of points[begin, end) outside(s, point), or end: outside's answer for each point,
// most of them settled by their squared distance alone.
std::size_t first_outside(const Sphere& s, const PointList& points, std::size_t begin,
                          std::size_t end);

}  // namespace detail

}  // namespace cloudshape::geometry
