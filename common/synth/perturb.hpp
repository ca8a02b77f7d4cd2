// Deliberate degradations of a clean synthetic cloud: sensor noise and stray points.
// Each is independent so robustness tests can dial them in one at a time.
#pragma once

#include "geometry/point_cloud.hpp"

#include <random>

namespace cloudshape::synth {

// Adds isotropic Gaussian noise: each coordinate gets N(0, sigma^2) independently, so the
// displacement along any fixed direction (e.g. a surface normal) has standard deviation sigma.
void add_gaussian_noise(PointList& points, double sigma, std::mt19937_64& rng);

// Appends round(fraction * points.size()) points uniform in the cloud's axis-aligned
// bounding box grown by 10% (5% of each extent on either side). `fraction` is relative to the
// cloud as passed in. An empty cloud is left unchanged (it has no bounding box).
void add_outliers(PointList& points, double fraction, std::mt19937_64& rng);

}  // namespace cloudshape::synth
