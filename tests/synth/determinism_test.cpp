// A fixed seed reproduces a cloud bit for bit; a different seed does not.
#include "synth/perturb.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

PointList generate(std::uint64_t seed, ShapeKind kind) {
  std::mt19937_64 rng(seed);
  const SolidSpec spec = random_solid(kind, rng, 5.0);
  PointList points = sample_solid_surface(spec, 2000, rng);
  add_gaussian_noise(points, 0.01, rng);
  add_outliers(points, 0.05, rng);
  return points;
}

TEST(Determinism, SameSeedSameCloud) {
  for (ShapeKind kind : all_shape_kinds()) {
    EXPECT_EQ(generate(99, kind), generate(99, kind)) << to_string(kind);
    EXPECT_NE(generate(99, kind), generate(100, kind)) << to_string(kind);
  }
}

}  // namespace
}  // namespace cloudshape::synth
