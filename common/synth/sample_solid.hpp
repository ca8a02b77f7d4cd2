// Area-uniform sampling of the closed surface of an analytic solid.
// The points are exact (no noise); perturb.hpp and visibility.hpp degrade them on purpose.
#pragma once

#include "geometry/point_cloud.hpp"
#include "synth/ground_truth.hpp"

#include <cstddef>
#include <random>

namespace cloudshape::synth {

// Exactly n points, uniform by area over every face, cap and lateral surface, in world
// coordinates (spec.pose applied). Throws std::invalid_argument on missing or invalid dimensions.
PointList sample_solid_surface(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng);

}  // namespace cloudshape::synth
