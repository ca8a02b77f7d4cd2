#include "surface_oracle.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

class OnSurface : public ::testing::TestWithParam<ShapeKind> {};

TEST_P(OnSurface, EveryPointLiesOnTheAnalyticSurfaceInRandomPoses) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 10; ++trial) {
    const SolidSpec spec = random_solid(GetParam(), rng, 0.5 + 40.0 * trial);
    const double tolerance = 1e-9 * characteristic_size(spec);
    const PointList points = sample_solid_surface(spec, 5000, rng);
    double worst = 0.0;
    for (const auto& p : points)
      worst = std::max(worst, std::abs(testing::surface_residual(spec, p)));
    EXPECT_LT(worst, tolerance) << to_string(spec.kind) << " trial " << trial;
  }
}

INSTANTIATE_TEST_SUITE_P(AllShapes, OnSurface, ::testing::ValuesIn(all_shape_kinds()),
                         [](const auto& info) { return to_string(info.param); });

TEST(SampleSolidSurface, ReturnsExactlyNPoints) {
  std::mt19937_64 rng(1);
  for (ShapeKind kind : all_shape_kinds())
    for (std::size_t n : {0u, 1u, 7u, 1000u, 12345u})
      EXPECT_EQ(sample_solid_surface(random_solid(kind, rng, 3.0), n, rng).size(), n);
}

TEST(SampleSolidSurface, RejectsInvalidDimensions) {
  std::mt19937_64 rng(1);
  SolidSpec spec{ShapeKind::cone, {{"radius", 1.0}}, {}};
  EXPECT_THROW(sample_solid_surface(spec, 10, rng), std::invalid_argument);
  spec.dimensions = {{"radius", 1.0}, {"height", -2.0}};
  EXPECT_THROW(sample_solid_surface(spec, 10, rng), std::invalid_argument);
  EXPECT_THROW(make_solid(ShapeKind::box, {1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace cloudshape::synth
