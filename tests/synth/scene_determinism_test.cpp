// A scene is a function of its recipe: the same seed gives the same frame bit for bit, another
// seed another scene, and scale 1000 the same frame and truth times 1000 (the unit is free).
#include <gtest/gtest.h>

#include "scene_test_support.hpp"

namespace cloudshape::synth {
namespace {

bool same_frame(const RangeImage& a, const RangeImage& b) {
  if (a.labels != b.labels || a.points.size() != b.points.size()) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const bool fa = std::isfinite(a.points[i].x()), fb = std::isfinite(b.points[i].x());
    if (fa != fb || (fa && a.points[i] != b.points[i])) return false;
  }
  return true;
}

TEST(SceneDeterminism, TheSameSeedGivesTheSameFrame) {
  auto options = testing::small_camera();
  options.depth_noise = 0.003;
  for (const auto layout : all_scene_layouts()) {
    const auto a = testing::capture(layout, 11, 1.0, options);
    const auto b = testing::capture(layout, 11, 1.0, options);
    const auto other = testing::capture(layout, 12, 1.0, options);
    EXPECT_TRUE(same_frame(a.image, b.image)) << to_string(layout);
    EXPECT_FALSE(same_frame(a.image, other.image)) << to_string(layout);
  }
}

class SceneUnitFree : public ::testing::TestWithParam<SceneLayout> {};

TEST_P(SceneUnitFree, ScaleThousandIsTheSameSceneTimesThousand) {
  auto options = testing::small_camera();
  options.depth_noise = 0.003;
  options.quantize = true;
  options.range_noise = 0.01;
  const auto metres = testing::capture(GetParam(), 21, 1.0, options);
  const auto millimetres = testing::capture(GetParam(), 21, 1000.0, options);
  ASSERT_EQ(metres.image.points.size(), millimetres.image.points.size());
  std::size_t label_changes = 0, finite = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < metres.image.points.size(); ++i) {
    if (metres.image.labels[i] != millimetres.image.labels[i]) {
      ++label_changes;
      continue;
    }
    if (metres.image.labels[i] == 0) continue;
    ++finite;
    const Eigen::Vector3d& m = metres.image.points[i];
    worst =
        std::max(worst, (millimetres.image.points[i] - 1000.0 * m).norm() / (1000.0 * m.norm()));
  }
  // Rounding may flip a pixel that grazes a silhouette; nothing else may differ.
  EXPECT_LE(label_changes, 2u);
  EXPECT_GT(finite, 500u);
  EXPECT_LT(worst, 1e-9);
  ASSERT_EQ(metres.scene.objects.size(), millimetres.scene.objects.size());
  for (std::size_t k = 0; k < metres.scene.objects.size(); ++k) {
    const SolidSpec& m = metres.scene.objects[k].solid;
    const SolidSpec& mm = millimetres.scene.objects[k].solid;
    ASSERT_EQ(m.kind, mm.kind);
    for (std::size_t d = 0; d < m.dimensions.size(); ++d)
      EXPECT_NEAR(mm.dimensions[d].second, 1000.0 * m.dimensions[d].second,
                  1e-9 * mm.dimensions[d].second);
    EXPECT_LT((mm.pose.center - 1000.0 * m.pose.center).norm(), 1e-9 * mm.pose.center.norm());
    EXPECT_LT((mm.pose.axes - m.pose.axes).norm(), 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, SceneUnitFree, ::testing::ValuesIn(all_scene_layouts()),
                         [](const auto& info) { return to_string(info.param); });

}  // namespace
}  // namespace cloudshape::synth
