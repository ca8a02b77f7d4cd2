// An object's noise off its surface, read from its points' neighbourhoods.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/kdtree.hpp"
#include "pipeline/surface_noise.hpp"

namespace cloudshape {
namespace {

// A 10 x 10 cm square sampled every 2 mm with `noise` off its plane.
PointList noisy_square(double noise, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  PointList points;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j) points.emplace_back(0.002 * i, 0.002 * j, noise * gauss(rng));
  return points;
}

// 16 neighbours about a point of a noisy face spread off their own plane by somewhat less than the
// noise (the plane takes some of it; the lower quartile of them, less again), and by about half of
// it where the noise exceeds the 2 mm spacing (the nearest points are then those whose noise
// agrees): between 0.4 and 1 times the drawn deviation, at 0.5, 1 and 3 mm.
TEST(SurfaceNoise, AFacesNoiseIsRead) {
  for (double noise : {0.0005, 0.001, 0.003}) {
    const PointList points = noisy_square(noise, 5);
    const geometry::KdTree tree(points);
    const double read = pipeline::surface_noise(points, tree, 16);
    EXPECT_GT(read, 0.4 * noise) << noise;
    EXPECT_LT(read, noise) << noise;
  }
}

// A noise-free box's corner and edges spread their neighbourhoods, its faces do not: the lower
// quartile reads no noise.
TEST(SurfaceNoise, ACleanBoxHasNone) {
  PointList points;
  for (int i = 0; i < 30; ++i)
    for (int j = 0; j < 30; ++j) {
      points.emplace_back(0.002 * i, 0.002 * j, 0.0);
      points.emplace_back(0.002 * i, 0.0, 0.002 * j + 0.002);
      points.emplace_back(0.0, 0.002 * i + 0.002, 0.002 * j + 0.002);
    }
  const geometry::KdTree tree(points);
  EXPECT_LT(pipeline::surface_noise(points, tree, 16), 1e-9);
}

// Fewer points than a neighbourhood: nothing is read.
TEST(SurfaceNoise, TooFewPoints) {
  const PointList points{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  const geometry::KdTree tree(points);
  EXPECT_EQ(pipeline::surface_noise(points, tree, 16), 0.0);
}

}  // namespace
}  // namespace cloudshape
