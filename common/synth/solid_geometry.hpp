// Local-frame vertices and constants of the polyhedral solids (see SolidSpec for the frames).
// Shared by the sampler and by tests that need the exact analytic surface.
#pragma once

#include <Eigen/Core>
#include <array>

namespace cloudshape::synth {

// Regular tetrahedron with centroid at the origin; vertex 0 is the apex on +x,
// vertex 1 lies in the x-y plane on the +y side.
std::array<Eigen::Vector3d, 4> tetrahedron_vertices(double edge);

// Circumradius of a regular pentagon with the given side.
double pentagon_circumradius(double side);

// Pentagon vertices in the y-z plane at x = 0, vertex 0 on +y, counter-clockwise about +x.
std::array<Eigen::Vector3d, 5> pentagon_vertices(double side);

}  // namespace cloudshape::synth
