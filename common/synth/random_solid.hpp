// Random solids with sensible proportions and a random pose, for suites and property tests.
// "Sensible" keeps every aspect ratio within about 1:3..3:1 (1:4 for cone/cylinder).
#pragma once

#include "synth/ground_truth.hpp"

#include <random>

namespace cloudshape::synth {

// `size` is the solid's largest extent (characteristic_size). The pose is uniformly rotated
// and its centre lies within +-size of the origin. Box dimensions come sorted, axes matching.
SolidSpec random_solid(ShapeKind kind, std::mt19937_64& rng, double size);

}  // namespace cloudshape::synth
