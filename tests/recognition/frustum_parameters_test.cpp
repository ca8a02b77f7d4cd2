// Frustum recognition against ground truth: whole and noisy; radii, height, base centre and the
// signed axis (larger end towards the smaller) within stated tolerances.
#include <gtest/gtest.h>

#include <random>

#include "new_shapes_support.hpp"
#include "synth/pose.hpp"

namespace cloudshape::newshapes {
namespace {

void check(const FrustumCase& c, double noise, std::uint64_t seed, double tolerance) {
  std::mt19937_64 rng(seed);
  const synth::Pose pose = synth::random_pose(rng, 100.0);
  const synth::SolidMesh mesh = synth::frustum_mesh(c.radius, c.top_radius, c.height, pose);
  const pipeline::ObjectResult o = recognise_one(sample(mesh, 20000, noise, seed + 1));
  ASSERT_EQ(o.shape, "frustum") << "seed " << seed << " " << o.reason;
  EXPECT_NEAR(dimension(o, "radius"), c.radius, tolerance * c.radius) << seed;
  EXPECT_NEAR(dimension(o, "top_radius"), c.top_radius, tolerance * c.radius) << seed;
  EXPECT_NEAR(dimension(o, "height"), c.height, tolerance * c.height) << seed;
  EXPECT_LT((o.center - pose.center).norm(), tolerance * mesh.size) << seed;
  EXPECT_GT(o.axes.row(0).dot(pose.axes.row(0)), std::cos(2.0 * 3.14159265358979 / 180.0)) << seed;
  EXPECT_FALSE(o.partial);
}

// A bucket, a lamp shade, a squat cup, a nearly-cylindrical tumbler (taper 25%: a taper under
// solve.frustum_min_taper, 20%, is named cylinder, as one noisy view of a can can show that much).
const std::vector<FrustumCase> kCases = {{40, 28, 60}, {50, 20, 40}, {45, 35, 25}, {32, 24, 90}};

TEST(FrustumParameters, Whole) {
  std::uint64_t seed = 100;
  for (const FrustumCase& c : kCases) check(c, 0.0, seed += 10, 0.01);
}

TEST(FrustumParameters, Noisy) {
  std::uint64_t seed = 200;
  for (const FrustumCase& c : kCases) check(c, 0.005, seed += 10, 0.02);
}

}  // namespace
}  // namespace cloudshape::newshapes
