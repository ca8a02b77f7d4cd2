// Random rigid poses for synthetic solids.
// Rotations are uniform over SO(3) so no orientation is favoured by the test suite.
#pragma once

#include "synth/ground_truth.hpp"

#include <Eigen/Core>
#include <random>

namespace cloudshape::synth {

// Uniformly distributed rotation matrix (from a uniform random unit quaternion).
Eigen::Matrix3d random_rotation(std::mt19937_64& rng);

// Uniform random rotation and a centre uniform in [-max_offset, max_offset]^3.
Pose random_pose(std::mt19937_64& rng, double max_offset);

}  // namespace cloudshape::synth
