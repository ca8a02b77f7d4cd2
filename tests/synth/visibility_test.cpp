// Hidden-point removal keeps the camera-facing part and drops everything behind it.
#include "synth/visibility.hpp"
#include "synth/mesh_sampling.hpp"
#include "synth/sample_solid.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Visibility, SphereKeepsTheNearCapOnly) {
  std::mt19937_64 rng(31);
  const std::size_t n = 50000;
  const PointList points = sample_solid_surface(make_solid(ShapeKind::sphere, {1.0}), n, rng);
  const Eigen::Vector3d camera(5.0, 0.0, 0.0);
  const PointList seen = visible_from(points, camera, visibility_resolution(4 * kPi, n));
  // From distance 5 the visible cap is x > 1/5: 40% of the sphere.
  const double fraction = static_cast<double>(seen.size()) / n;
  EXPECT_GT(fraction, 0.33);
  EXPECT_LE(fraction, 0.41);
  for (const auto& p : seen) EXPECT_GT(p.x(), 0.0) << p.transpose();
}

TEST(Visibility, ThinBoxLosesItsBackFace) {
  std::mt19937_64 rng(32);
  const SolidSpec slab = make_solid(ShapeKind::box, {10.0, 10.0, 1.0});
  const std::size_t n = 20000;
  const PointList points = sample_solid_surface(slab, n, rng);
  const PointList seen = visible_from(points, Eigen::Vector3d(0.3, -0.2, 30.0),
                                      visibility_resolution(surface_area(slab), n));
  std::size_t front = 0;
  for (const auto& p : seen) {
    EXPECT_GT(p.z(), -0.5 + 1e-9) << "back face point survived: " << p.transpose();
    if (p.z() > 0.5 - 1e-9) ++front;
  }
  // The whole front face is seen (100 of 240 area units).
  EXPECT_NEAR(static_cast<double>(front) / n, 100.0 / 240.0, 0.02);
}

TEST(Visibility, SampleVisibleReturnsExactlyNFromTheVisibleSide) {
  std::mt19937_64 rng(33);
  const SolidSpec cube = make_solid(ShapeKind::box, {2.0, 2.0, 2.0});
  const Eigen::Vector3d camera(0.0, 0.0, 10.0);
  const PointList seen =
      sample_visible([&](std::size_t m) { return sample_solid_surface(cube, m, rng); },
                     surface_area(cube), 5000, camera, rng);
  ASSERT_EQ(seen.size(), 5000u);
  // The side faces are hidden behind the top face's edges; the z-buffer's depth tolerance lets
  // a thin sliver just below those edges through (documented in visibility.hpp).
  std::size_t top = 0;
  for (const auto& p : seen) {
    EXPECT_GT(p.z(), 0.6);
    if (p.z() > 1.0 - 1e-9) ++top;
  }
  EXPECT_GT(top, 0.9 * 5000);
}

TEST(Visibility, ObliqueCubeShowsThreeFacesAndFewHiddenPoints) {
  std::mt19937_64 rng(34);
  const std::size_t n = 60000;
  const PointList points =
      sample_solid_surface(make_solid(ShapeKind::box, {2.0, 2.0, 2.0}), n, rng);
  const PointList seen =
      visible_from(points, Eigen::Vector3d(10, 7, 5), visibility_resolution(24.0, n));
  std::size_t hidden = 0;
  for (const auto& p : seen)
    if ((p.array() < -1.0 + 1e-9).any()) ++hidden;
  // Three of six faces face the camera.
  EXPECT_GT(seen.size() - hidden, 0.9 * n / 2);
  EXPECT_LT(hidden, 0.1 * seen.size());
}

TEST(Visibility, RejectsBadResolutionAndHandlesEmpty) {
  EXPECT_THROW(visible_from({Point(1, 0, 0)}, Point::Zero(), 0.0), std::invalid_argument);
  EXPECT_TRUE(visible_from({}, Point::Zero(), 1.0).empty());
}

}  // namespace
}  // namespace cloudshape::synth
