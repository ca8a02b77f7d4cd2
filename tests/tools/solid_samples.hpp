// The sample clouds the recognize CLI tests share: a random solid of a kind, sampled on its surface.
// One seed gives one solid and one sampling, so two tests that name the same seed see the same points.
#pragma once

#include <cstdint>
#include <random>

#include "geometry/point_cloud.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape::testing {

// The solid behind sample(kind, n, seed): the same generator draws it first.
inline synth::SolidSpec solid(synth::ShapeKind kind, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  return synth::random_solid(kind, rng, 40.0);
}

inline PointList sample(synth::ShapeKind kind, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const synth::SolidSpec spec = synth::random_solid(kind, rng, 40.0);
  return synth::sample_solid_surface(spec, n, rng);
}

}  // namespace cloudshape::testing
