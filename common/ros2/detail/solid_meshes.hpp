// Triangle meshes of the solids RViz has no primitive for, in the solid's own frame (x its axis),
// each face wound counter-clockwise seen from outside.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace cloudshape::ros2::detail {

using Triangles = std::vector<Eigen::Vector3d>;  // every three vertices one triangle

// A truncated cone along x from its base (x = 0, base_radius) to x = height (top_radius; 0 for a
// cone), the base disc and a top disc when top_radius > 0 included.
Triangles revolved(double base_radius, double top_radius, double height, int segments);

// A right prism along x from -height/2 to height/2 whose cross-section in the y z plane is
// `polygon` (simple, convex or not, counter-clockwise); caps cut into triangles by ear clipping.
Triangles prism(const std::vector<Eigen::Vector2d>& polygon, double height);

// The four faces of a tetrahedron, each turned away from the opposite vertex.
Triangles tetrahedron(const std::array<Eigen::Vector3d, 4>& vertices);

}  // namespace cloudshape::ros2::detail
