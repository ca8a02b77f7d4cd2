// The outline of a flat face from its points: an occupancy grid traced around (Moore
// neighbours), simplified (Douglas-Peucker) to the polygon a prism's cap shows, convex or not.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/polygon.hpp"

namespace cloudshape::pipeline::detail {

// `points`: the face's points in its own 2-D frame. `cell`: the grid's cell, about twice their
// spacing, so the face fills it; `tolerance`: how far the simplified outline may stray from the
// traced one. Counter-clockwise; empty when the points do not make one region.
geometry::Polygon2 face_outline_polygon(const std::vector<Eigen::Vector2d>& points, double cell,
                                        double tolerance);

}  // namespace cloudshape::pipeline::detail
