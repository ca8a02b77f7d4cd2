// Simple 2-D polygons (convex or not), vertices in order: area, centroid, signed distance,
// ear-clipping triangulation. Shared by the prism fitter, the synthetic prisms and the markers.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

namespace cloudshape::geometry {

using Polygon2 = std::vector<Eigen::Vector2d>;

// The regular polygon of `sides` corners on the circle of `circumradius` about the origin,
// counter-clockwise, the first at `first_angle` (radians) from the x axis.
Polygon2 regular_polygon(int sides, double circumradius, double first_angle = 0.0);

// Positive for a counter-clockwise polygon.
double signed_area(const Polygon2& polygon);

double perimeter(const Polygon2& polygon);

// The area centroid (the mean of the vertices for a degenerate polygon).
Eigen::Vector2d area_centroid(const Polygon2& polygon);

// Distance to the outline, negative inside (even-odd rule).
double signed_distance(const Polygon2& polygon, const Eigen::Vector2d& p);

// True when no two non-neighbouring edges touch.
bool is_simple(const Polygon2& polygon);

// Ear clipping of a counter-clockwise simple polygon: index triples, counter-clockwise. A
// polygon that is not simple may have no ear left: what was cut so far is returned.
std::vector<std::array<std::size_t, 3>> triangulate(const Polygon2& polygon);

}  // namespace cloudshape::geometry
