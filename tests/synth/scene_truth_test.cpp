// Exact truth of rendered scenes: every labelled point lies on the surface its label names (the
// analytic oracle, to 1e-9 of the scene unit), inside no other solid and seen along a clear line.
#include <gtest/gtest.h>

#include <map>

#include "scene_test_support.hpp"

namespace cloudshape::synth {
namespace {

using testing::capture;

struct Case {
  SceneLayout layout;
  std::uint64_t seed;
};

class SceneTruth : public ::testing::TestWithParam<Case> {};

TEST_P(SceneTruth, EveryLabelledPointLiesOnItsSurfaceAndIsTheFirstHit) {
  const auto [layout, seed] = GetParam();
  const double scale = 1.0;
  const SceneCapture c = capture(layout, seed, scale);
  const double tol = 1e-9 * scale;
  std::map<std::uint32_t, std::size_t> count;
  std::size_t blocked = 0;
  for (std::size_t i = 0; i < c.image.points.size(); ++i) {
    const std::uint32_t label = c.image.labels[i];
    const Eigen::Vector3d& p = c.image.points[i];
    ASSERT_EQ(label == 0, !std::isfinite(p.x())) << "pixel " << i;
    if (label == 0) continue;
    ++count[label];
    if (label >= 20) {
      const SceneObject* o = testing::object_with(c.scene, label);
      ASSERT_NE(o, nullptr) << label;
      ASSERT_NEAR(testing::surface_residual(o->solid, p), 0.0, tol)
          << "pixel " << i << " label " << label;
    } else {
      const SceneRectangle* r = testing::structure_with(c.scene, label);
      ASSERT_NE(r, nullptr) << label;
      ASSERT_NEAR(testing::plane_distance(*r, p), 0.0, tol) << "pixel " << i;
      ASSERT_TRUE(testing::within(*r, p, tol)) << "pixel " << i;
    }
    for (const auto& o : c.scene.objects)
      ASSERT_GE(testing::surface_residual(o.solid, p), -tol)
          << "pixel " << i << " inside " << o.label;
    // The sight line from the sensor (the origin) stays out of every solid before the point.
    for (int k = 1; k < 64; ++k) {
      const Eigen::Vector3d q = p * (k / 64.0);
      for (const auto& o : c.scene.objects)
        blocked += testing::surface_residual(o.solid, q) < -tol ? 1 : 0;
    }
  }
  EXPECT_EQ(blocked, 0u);
  // Every object and the support plane show up: the camera frames the whole scene.
  EXPECT_GT(count[1], 100u);
  for (const auto& o : c.scene.objects) EXPECT_GT(count[o.label], 5u) << "object " << o.label;
}

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const auto layout : all_scene_layouts())
    for (std::uint64_t seed : {1, 2, 3}) all.push_back({layout, seed});
  return all;
}

INSTANTIATE_TEST_SUITE_P(Layouts, SceneTruth, ::testing::ValuesIn(cases()), [](const auto& info) {
  return to_string(info.param.layout) + "_seed" + std::to_string(info.param.seed);
});

TEST(SceneTruth, LabelsFollowMosd) {
  const SceneCapture c = capture(SceneLayout::wall, 4, 1.0, testing::small_camera(), 4, 2);
  ASSERT_EQ(c.scene.objects.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(c.scene.objects[i].label, 20 + 10 * i);
  ASSERT_EQ(c.scene.structure.size(), 3u);
  EXPECT_EQ(c.scene.structure[0].kind, "plane");
  EXPECT_EQ(c.scene.structure[0].label, 1u);
  EXPECT_EQ(c.scene.structure[1].label, 2u);
  EXPECT_EQ(c.scene.structure[2].label, 3u);
}

TEST(SceneTruth, DepthNoiseGrowsWithDepthSquared) {
  auto options = testing::small_camera();
  const SceneCapture clean = capture(SceneLayout::row, 5, 1.0, options);
  options.depth_noise = 0.003;
  const SceneCapture noisy = capture(SceneLayout::row, 5, 1.0, options);
  double sum2 = 0.0;
  std::size_t n = 0, beyond = 0;
  for (std::size_t i = 0; i < clean.image.points.size(); ++i) {
    ASSERT_EQ(clean.image.labels[i], noisy.image.labels[i]);
    if (clean.image.labels[i] == 0) continue;
    const double z = clean.image.points[i].z();
    const double normalised = (noisy.image.points[i].z() - z) / (0.003 * z * z);
    sum2 += normalised * normalised;
    beyond += std::abs(normalised) > 5.0 ? 1 : 0;
    ++n;
  }
  ASSERT_GT(n, 5000u);
  // Depth errors divided by k z^2 are standard normal: unit variance, nothing past 5 sigma.
  EXPECT_NEAR(std::sqrt(sum2 / n), 1.0, 0.05);
  EXPECT_EQ(beyond, 0u);
}

TEST(SceneTruth, QuantisedDepthsTakeDisparitySteps) {
  auto options = testing::small_camera();
  options.quantize = true;
  const SceneCapture c = capture(SceneLayout::touching, 6, 1.0, options);
  const double fb = 0.5 * 160 / std::tan(0.5 * 58.0 * 3.14159265358979323846 / 180.0) * 0.075;
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.image.points.size(); ++i) {
    if (c.image.labels[i] == 0) continue;
    const double steps = fb / c.image.points[i].z() / 0.125;
    ASSERT_NEAR(steps, std::round(steps), 1e-6) << "pixel " << i;
    ++n;
  }
  EXPECT_GT(n, 1000u);
}

// Whether one of `samples` points of the open segment from a to b lies inside a solid.
bool segment_blocked(const Scene& scene, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                     double tol, int samples) {
  for (int k = 1; k < samples; ++k) {
    const Eigen::Vector3d q = a + (b - a) * (static_cast<double>(k) / samples);
    for (const auto& o : scene.objects)
      if (testing::surface_residual(o.solid, q) < -tol) return true;
  }
  return false;
}

TEST(SceneTruth, ProjectorShadowsEmptyExactlyThePixelsTheProjectorCannotLight) {
  auto options = testing::small_camera();
  const SceneCapture lit = capture(SceneLayout::touching, 3, 1.0, options);
  options.shadows = true;
  const SceneCapture shaded = capture(SceneLayout::touching, 3, 1.0, options);
  const Eigen::Vector3d projector(0.075, 0.0, 0.0);
  std::size_t removed = 0, removed_and_blocked = 0;
  for (std::size_t i = 0; i < lit.image.points.size(); ++i) {
    if (shaded.image.labels[i] != 0) {
      ASSERT_EQ(shaded.image.labels[i], lit.image.labels[i]);
      ASSERT_EQ(shaded.image.points[i], lit.image.points[i]);
      ASSERT_FALSE(segment_blocked(shaded.scene, projector, shaded.image.points[i], 1e-9, 256))
          << "pixel " << i;
    } else if (lit.image.labels[i] != 0) {
      ++removed;
      removed_and_blocked +=
          segment_blocked(lit.scene, projector, lit.image.points[i], 0.0, 2000) ? 1 : 0;
    }
  }
  // Shadows fall beside the objects; sampling the segment may miss a shadow's thin edge.
  EXPECT_GT(removed, 20u);
  EXPECT_GE(removed_and_blocked, 0.9 * removed);
}

TEST(SceneTruth, FlyingPixelsFallBetweenTheSurfacesOfADepthJump) {
  auto options = testing::small_camera();
  const SceneCapture clean = capture(SceneLayout::stacked, 7, 1.0, options);
  options.flying_pixels = 1.0;
  const SceneCapture flying = capture(SceneLayout::stacked, 7, 1.0, options);
  ASSERT_EQ(clean.image.labels, flying.image.labels);
  const std::size_t w = 160, h = 120;
  std::size_t moved = 0;
  for (std::size_t i = 0; i < w * h; ++i) {
    if (clean.image.labels[i] == 0 || clean.image.points[i] == flying.image.points[i]) continue;
    ++moved;
    const double z = clean.image.points[i].z(), fz = flying.image.points[i].z();
    bool between = false;
    for (const long step : {-1L, 1L, -static_cast<long>(w), static_cast<long>(w)}) {
      const long j = static_cast<long>(i) + step;
      if (j < 0 || j >= static_cast<long>(w * h) || (std::abs(step) == 1 && j / w != i / w))
        continue;
      const double nz = clean.image.points[j].z();
      if (!std::isfinite(nz) || std::abs(nz - z) <= 0.05 * z) continue;
      between = between || (fz - z) * (fz - nz) <= 0.0;
    }
    ASSERT_TRUE(between) << "pixel " << i << " moved off every jump";
  }
  EXPECT_GT(moved, 100u);
}

}  // namespace
}  // namespace cloudshape::synth
