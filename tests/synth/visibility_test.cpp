// Exact visibility of the analytic solids, and the sampler that keeps n visible points.
#include "synth/visibility.hpp"
#include "synth/sample_solid.hpp"
#include "synth/solid_visibility.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

// sample_visible oversamples so that exactly n points survive the filter, all of them visible.
TEST(SampleVisible, ReturnsExactlyNFromTheVisibleSide) {
  std::mt19937_64 rng(33);
  const SolidSpec cube = make_solid(ShapeKind::box, {2.0, 2.0, 2.0});
  const Eigen::Vector3d camera(0.0, 0.0, 10.0);
  const PointList seen = sample_visible(
      [&](std::size_t m) { return sample_solid_surface(cube, m, rng); },
      [&](const PointList& points) { return visible_on_solids(points, {cube}, camera); }, 5000,
      rng);
  ASSERT_EQ(seen.size(), 5000u);
  // Seen from straight above, only the top face is visible (1/6 of the surface).
  for (const auto& p : seen) EXPECT_GT(p.z(), 1.0 - 1e-9) << p.transpose();
}

// The exact test for analytic solids: no point of a face turned away survives, every point
// of a face turned towards the camera does, and a solid hides what lies behind it.
TEST(SolidVisibility, CubeKeepsExactlyItsCameraFacingFaces) {
  std::mt19937_64 rng(35);
  const SolidSpec cube = make_solid(ShapeKind::box, {2.0, 2.0, 2.0});
  const PointList points = sample_solid_surface(cube, 30000, rng);
  const Eigen::Vector3d camera(10, 7, 5);
  const PointList seen = visible_on_solids(points, {cube}, camera);
  std::size_t expected = 0;
  for (const auto& p : points)
    if (p.x() > 1.0 - 1e-9 || p.y() > 1.0 - 1e-9 || p.z() > 1.0 - 1e-9) ++expected;
  EXPECT_EQ(seen.size(), expected);
  for (const auto& p : seen) EXPECT_FALSE((p.array() < -1.0 + 1e-9).any()) << p.transpose();
}

TEST(SolidVisibility, ASolidHidesTheOneBehindIt) {
  std::mt19937_64 rng(36);
  Pose near_pose, far_pose;
  far_pose.center = Eigen::Vector3d(0, 0, -5);
  const SolidSpec front = make_solid(ShapeKind::sphere, {1.0}, near_pose);
  const SolidSpec back = make_solid(ShapeKind::sphere, {0.5}, far_pose);
  PointList points = sample_solid_surface(back, 5000, rng);
  const Eigen::Vector3d camera(0, 0, 10);
  // Seen from +z, the small sphere lies wholly in the big one's shadow.
  EXPECT_TRUE(visible_on_solids(points, {front, back}, camera).empty());
  // From the side it is in plain view: its camera-facing half survives.
  const std::size_t side = visible_on_solids(points, {front, back}, Eigen::Vector3d(10, 0, -5)).size();
  EXPECT_NEAR(static_cast<double>(side) / points.size(), 0.5, 0.05);
}

}  // namespace
}  // namespace cloudshape::synth
