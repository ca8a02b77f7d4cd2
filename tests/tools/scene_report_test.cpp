// The scene benchmark's tallies: per-category sums, the "all" row, false objects per scene,
// IoU only over measured objects, and the median / maximum of the frame times.
#include <gtest/gtest.h>

#include "scene_report.hpp"

namespace cloudshape::bench {
namespace {

SceneRun run(const std::string& category, int right, int wrong, int missed, int false_objects,
             double wall_ms, std::vector<double> ious) {
  SceneRun r;
  r.category = category;
  r.wall_ms = wall_ms;
  r.total_ms = wall_ms - 1.0;
  r.cpu_ms = wall_ms - 2.0;
  for (int k = 0; k < right + wrong + missed; ++k) {
    ObjectScore o;
    o.object = static_cast<std::uint32_t>(2 + k);
    o.outcome = k < right           ? ObjectOutcome::right
                : k < right + wrong ? ObjectOutcome::wrong_shape
                                    : ObjectOutcome::missed;
    if (o.outcome == ObjectOutcome::wrong_shape) o.reported_shapes = {"cone"};
    if (static_cast<std::size_t>(k) < ious.size()) o.iou = ious[static_cast<std::size_t>(k)];
    r.score.objects.push_back(o);
  }
  r.score.right = right;
  r.score.wrong_shape = wrong;
  r.score.missed = missed;
  r.score.false_objects = false_objects;
  return r;
}

TEST(SceneReport, RowsSumPerCategoryInTheTruthOrderThenAll) {
  const std::vector<SceneRun> runs = {
      run("cylindric", 1, 1, 0, 1, 30.0, {0.5, 0.7}), run("boxes", 2, 0, 1, 0, 10.0, {}),
      run("cylindric", 0, 0, 2, 2, 50.0, {}), run("other", 1, 0, 0, 0, 20.0, {0.9})};
  const auto rows = tally_scenes(runs, {"boxes", "stacked_boxes", "cylindric"});
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].first, "boxes");
  EXPECT_EQ(rows[1].first, "cylindric");
  EXPECT_EQ(rows[2].first, "other");
  EXPECT_EQ(rows[3].first, "all");
  const SceneTally& cyl = rows[1].second;
  EXPECT_EQ(cyl.scenes, 2);
  EXPECT_EQ(cyl.objects, 4);
  EXPECT_EQ(cyl.right, 1);
  EXPECT_EQ(cyl.wrong_shape, 1);
  EXPECT_EQ(cyl.missed, 2);
  EXPECT_EQ(cyl.false_objects, 3);
  EXPECT_EQ(cyl.wrong_as, (std::map<std::string, int>{{"cone", 1}}));
  EXPECT_EQ(cyl.ious, (std::vector<double>{0.5, 0.7}));
  EXPECT_DOUBLE_EQ(median_of(cyl.wall_ms), 40.0);
  EXPECT_DOUBLE_EQ(max_of(cyl.wall_ms), 50.0);
  const SceneTally& all = rows[3].second;
  EXPECT_EQ(all.scenes, 4);
  EXPECT_EQ(all.objects, 8);
  EXPECT_EQ(all.right, 4);
  EXPECT_EQ(all.false_objects, 3);
  EXPECT_EQ(all.ious.size(), 3u);
  EXPECT_DOUBLE_EQ(median_of(all.wall_ms), 25.0);
  EXPECT_DOUBLE_EQ(median_of(all.total_ms), 24.0);
  EXPECT_DOUBLE_EQ(max_of(all.cpu_ms), 48.0);
}

TEST(SceneReport, JsonCarriesFalsePerSceneAndNullIouWhenNothingWasMeasured) {
  const std::vector<SceneRun> runs = {run("boxes", 1, 0, 0, 1, 10.0, {}),
                                      run("boxes", 1, 0, 0, 0, 12.0, {})};
  const auto rows = tally_scenes(runs, {"boxes"});
  const auto j = scenes_json(runs, rows, nlohmann::ordered_json::object());
  const auto& boxes = j.at("rows").at(0);
  EXPECT_DOUBLE_EQ(boxes.at("false_per_scene").get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(boxes.at("right_pct").get<double>(), 100.0);
  EXPECT_TRUE(boxes.at("iou_mean").is_null());
  EXPECT_EQ(j.at("rows").at(1).at("category"), "all");
  EXPECT_EQ(j.at("scenes").size(), 2u);
}

}  // namespace
}  // namespace cloudshape::bench
