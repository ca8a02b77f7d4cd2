// The one-call cloud builder: counts, determinism, occlusion between objects, recorded info.
#include "synth/synthetic_cloud.hpp"
#include "surface_oracle.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

TEST(SyntheticCloud, CountsAndInfo) {
  const SolidSpec box = make_solid(ShapeKind::box, {3, 2, 1});
  CloudOptions options;
  options.points = 4000;
  options.noise_sigma = 0.01;
  options.outlier_fraction = 0.1;
  const auto cloud = make_synthetic_cloud({box}, options, 5);
  EXPECT_EQ(cloud.points.size(), 4400u);
  EXPECT_EQ(cloud.info.points, 4400u);
  EXPECT_EQ(cloud.info.outliers, 400u);
  EXPECT_EQ(cloud.info.seed, 5u);
  EXPECT_EQ(cloud.points, make_synthetic_cloud({box}, options, 5).points);
}

TEST(SyntheticCloud, SeveralObjectsShareByAreaAndOccludeEachOther) {
  Pose left, right;
  left.center = {-5, 0, 0};
  right.center = {5, 0, 0};
  const SolidSpec big = make_solid(ShapeKind::sphere, {2.0}, left);
  const SolidSpec small = make_solid(ShapeKind::sphere, {1.0}, right);
  CloudOptions options;
  options.points = 50000;
  const auto cloud = make_synthetic_cloud({big, small}, options, 6);
  std::size_t on_big = 0;
  for (const auto& p : cloud.points) {
    const double a = std::abs(testing::surface_residual(big, p));
    const double b = std::abs(testing::surface_residual(small, p));
    EXPECT_LT(std::min(a, b), 1e-9);
    on_big += a < b ? 1 : 0;
  }
  EXPECT_NEAR(on_big / 50000.0, 0.8, 0.01);  // area ratio 4:1

  // Seen along the line of centres, the big sphere hides the small one completely.
  options.view = Eigen::Vector3d(-30, 0, 0);
  const auto seen = make_synthetic_cloud({big, small}, options, 7);
  EXPECT_EQ(seen.points.size(), 50000u);
  for (const auto& p : seen.points) EXPECT_LT(p.x(), -3.0);
  EXPECT_TRUE(seen.info.view.has_value());
}

TEST(SyntheticCloud, RegeneratesFromItsGroundTruth) {
  std::mt19937_64 rng(8);
  CloudOptions options;
  options.points = 3000;
  options.noise_sigma = 0.02;
  options.outlier_fraction = 0.05;
  options.view = Eigen::Vector3d(40, -10, 25);
  options.density.falloff_from = Eigen::Vector3d(30, 0, 0);
  options.density.patchiness = 0.5;
  const auto cloud = make_synthetic_cloud({random_solid(ShapeKind::cone, rng, 10.0)}, options,
                                          0xfedcba9876543210ull);
  const auto text = ground_truth_json("c.pcd", cloud.objects, cloud.info).dump();
  EXPECT_EQ(regenerate_from_ground_truth(nlohmann::json::parse(text)).points, cloud.points);
  EXPECT_THROW(regenerate_from_ground_truth(nlohmann::json::parse(R"({"objects": []})")),
               std::invalid_argument);
}

// Density falling with the squared distance from a camera: a sphere's far half gets far
// fewer points than its near half, and the count asked for is still met.
TEST(SyntheticCloud, DensityFallsWithDistanceAndPatchesLosePoints) {
  const SolidSpec sphere = make_solid(ShapeKind::sphere, {1.0});
  CloudOptions options;
  options.points = 20000;
  options.density.falloff_from = Eigen::Vector3d(3, 0, 0);
  const auto cloud = make_synthetic_cloud({sphere}, options, 9);
  ASSERT_EQ(cloud.points.size(), 20000u);
  std::size_t near = 0;
  for (const auto& p : cloud.points) near += p.x() > 0.0 ? 1 : 0;
  // Kept with probability (2 / d)^2: ~0.59 on the near half, ~0.27 on the far half.
  EXPECT_NEAR(static_cast<double>(near) / cloud.points.size(), 0.69, 0.03);

  CloudOptions patchy;
  patchy.points = 20000;
  patchy.density.patchiness = 1.0;
  const auto holes = make_synthetic_cloud({sphere}, patchy, 10);
  ASSERT_EQ(holes.points.size(), 20000u);
  // Patches emptied at their centres: some 0.1-radius cap of the sphere now holds (almost)
  // no point, where an even sampling puts ~50 in every one.
  std::mt19937_64 rng(11);
  std::size_t emptiest = holes.points.size();
  for (const auto& c : sample_solid_surface(sphere, 200, rng)) {
    std::size_t in = 0;
    for (const auto& p : holes.points) in += (p - c).norm() < 0.1 ? 1 : 0;
    emptiest = std::min(emptiest, in);
  }
  EXPECT_LT(emptiest, 5u);
  EXPECT_THROW(thin_by_density(holes.points, {std::nullopt, 1.5}, rng), std::invalid_argument);
}

TEST(SyntheticCloud, RejectsNoObjects) {
  EXPECT_THROW(make_synthetic_cloud({}, CloudOptions{}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace cloudshape::synth
