// The truth files of a scene: the objects read back through solids_from_ground_truth as the very
// solids that were rendered, with their labels and relations; the sidecar maps each label group
// that has points to its shape, in the {"groups": {"20": "box"}} form benchmarks read.
#include <gtest/gtest.h>

#include <algorithm>

#include "scene_test_support.hpp"
#include "synth/ground_truth_json.hpp"
#include "synth/scene_truth_json.hpp"

namespace cloudshape::synth {
namespace {

TEST(SceneTruthJson, ObjectsReadBackAsTheRenderedSolids) {
  SceneRecipe recipe;
  recipe.layout = SceneLayout::stacked;
  recipe.count = 4;
  recipe.seed = 8;
  const SceneCapture c = capture_scene(recipe, testing::small_camera());
  // Through text, as a reader of the file gets it.
  const auto doc = nlohmann::json::parse(
      scene_truth_json("s.pcd", recipe, c.generated, c.scene, c.image, c.sensor).dump());
  const auto solids = solids_from_ground_truth(doc);
  ASSERT_EQ(solids.size(), c.scene.objects.size());
  std::size_t labelled_points = 0;
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const SolidSpec& want = c.scene.objects[i].solid;
    EXPECT_EQ(solids[i].kind, want.kind);
    for (std::size_t d = 0; d < want.dimensions.size(); ++d)
      EXPECT_DOUBLE_EQ(solids[i].dimensions[d].second, want.dimensions[d].second);
    EXPECT_LT((solids[i].pose.center - want.pose.center).norm(), 1e-12);
    EXPECT_LT((solids[i].pose.axes - want.pose.axes).norm(), 1e-12);
    EXPECT_EQ(doc["objects"][i]["label"], c.scene.objects[i].label);
    std::size_t seen = 0;
    for (const auto label : c.image.labels) seen += label == c.scene.objects[i].label ? 1 : 0;
    EXPECT_EQ(doc["objects"][i]["visible_points"], seen);
    labelled_points += seen;
  }
  EXPECT_EQ(doc["layout"], "stacked");
  EXPECT_EQ(doc["stacked"], nlohmann::json::parse("[[30, 20], [40, 30]]"));
  EXPECT_EQ(doc["structure"][0]["label"], 1);
  EXPECT_GT(doc["points"].get<std::size_t>(), labelled_points);  // the table's points too
}

TEST(SceneTruthJson, GroupsNameTheShapeOfEveryLabelWithPoints) {
  SceneRecipe recipe;
  recipe.layout = SceneLayout::row;
  recipe.count = 5;
  recipe.seed = 5;
  SceneCapture c = capture_scene(recipe, testing::small_camera());
  // An object with no point in the frame has no group.
  for (auto& label : c.image.labels)
    if (label == 30) label = 1;
  const auto groups = scene_groups_json(c.scene, c.image);
  ASSERT_TRUE(groups.contains("groups"));
  std::size_t with_points = 0;
  for (const auto& o : c.scene.objects) {
    const bool seen = std::count(c.image.labels.begin(), c.image.labels.end(), o.label) > 0;
    with_points += seen ? 1 : 0;
    if (seen)
      EXPECT_EQ(groups["groups"][std::to_string(o.label)], to_string(o.solid.kind));
    else
      EXPECT_FALSE(groups["groups"].contains(std::to_string(o.label)));
  }
  EXPECT_FALSE(groups["groups"].contains("30"));
  EXPECT_GE(with_points, 3u);
  EXPECT_EQ(groups["groups"].size(), with_points);
}

}  // namespace
}  // namespace cloudshape::synth
