// The convex hull of points in a plane (Andrew's monotone chain), for outlines and for the
// minimum-area rectangles of rotating calipers.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace cloudshape::geometry {

// Counter-clockwise, no collinear and no repeated first point; fewer than 3 points come back
// sorted as they are.
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points);

// The points, in their order, less those inside the octagon of the extreme points in eight
// directions by more than rounding can move a point (Akl-Toussaint): none of those can be a
// hull vertex, so convex_hull_2d of the rest is the hull of all (tests compare the two), and it
// sorts only the points near the outline.
std::vector<Eigen::Vector2d> hull_candidates(const std::vector<Eigen::Vector2d>& points);

}  // namespace cloudshape::geometry
