// Exact support function and bounding radius of the posed analytic solids: how far a solid
// reaches along a direction, so scenes can put solids flush on planes, walls and each other.
#pragma once

#include <Eigen/Core>

#include "synth/ground_truth.hpp"

namespace cloudshape::synth {

// max over the solid of direction . x (direction need not be unit; the result scales with it).
double support(const SolidSpec& spec, const Eigen::Vector3d& direction);

// Radius of a sphere about pose.center that contains the whole solid.
double bounding_radius(const SolidSpec& spec);

// Moves the solid by `offset` (its shape and orientation are kept).
void translate(SolidSpec& spec, const Eigen::Vector3d& offset);

}  // namespace cloudshape::synth
