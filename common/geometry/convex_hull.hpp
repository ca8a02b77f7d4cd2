// The convex hull of points in a plane (Andrew's monotone chain), for outlines and for the
// minimum-area rectangles of rotating calipers.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cloudshape::geometry {

// Counter-clockwise, no collinear and no repeated first point; fewer than 3 points come back
// sorted as they are.
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points);

}  // namespace cloudshape::geometry
