// Synthetic scenes with exact truth (cloudshape-synth scene): objects resting on a table,
// touching, stacked, in a row and against a wall, seen by one depth camera: every object comes
// out as one segment of its own, and nothing else does.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "captured_scene.hpp"
#include "config/pipeline_config.hpp"
#include "kinect_faults.hpp"
#include "segment/segment_scene.hpp"
#include "synth/range_sensor.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape::segment {
namespace {

struct Scored {
  std::size_t objects = 0;        // label groups of at least kMinPoints points
  std::size_t found = 0;          // matched by a segment with IoU >= kMinIou
  std::size_t false_objects = 0;  // segments whose majority is no object (table, wall)
  std::string detail;
};

constexpr std::size_t kMinPoints = 200;
constexpr double kMinIou = 0.8;

synth::CaptureOptions small_camera() {
  synth::CaptureOptions options;
  options.width = 320;
  options.height = 240;
  return options;
}

// How the segmentation with `cfg` finds the objects of a captured scene.
Scored score(const CapturedScene& scene, const config::SegmentConfig& cfg) {
  const std::vector<std::uint32_t>& labels = scene.labels;
  std::map<std::uint32_t, std::size_t> group_size = scene.size;
  const SceneSegmentation s = segment_scene(scene.points, scene.grid, cfg);
  Scored out;
  std::map<std::uint32_t, double> best_iou;
  for (const auto& object : s.objects) {
    std::map<std::uint32_t, std::size_t> votes;
    for (std::uint32_t i : object) ++votes[labels[i]];
    const auto major = std::max_element(votes.begin(), votes.end(),
                                        [](const auto& a, const auto& b) { return a.second < b.second; });
    if (major->first < 20) {
      ++out.false_objects;
      out.detail += " false(label " + std::to_string(major->first) + ", " + std::to_string(object.size()) + ")";
      continue;
    }
    const double iou = static_cast<double>(major->second) /
                       static_cast<double>(object.size() + group_size[major->first] - major->second);
    best_iou[major->first] = std::max(best_iou[major->first], iou);
  }
  for (const auto& [label, size] : group_size) {
    if (label < 20 || size < kMinPoints) continue;
    ++out.objects;
    const double iou = best_iou.count(label) ? best_iou[label] : 0.0;
    if (iou >= kMinIou) ++out.found;
    out.detail += " " + std::to_string(label) + ":" + std::to_string(iou).substr(0, 4);
  }
  return out;
}

Scored score(const synth::SceneRecipe& recipe,
             const config::SegmentConfig& cfg = config::PipelineConfig{}.segment,
             const synth::CaptureOptions& options = small_camera()) {
  return score(capture_points(recipe, options), cfg);
}

void expect_every_object(synth::SceneLayout layout, std::size_t count) {
  for (std::uint64_t seed : {1, 2, 3, 4}) {
    synth::SceneRecipe recipe;
    recipe.layout = layout;
    recipe.count = count;
    recipe.seed = seed;
    const Scored s = score(recipe);
    SCOPED_TRACE(synth::to_string(layout) + " seed " + std::to_string(seed) + ":" + s.detail);
    EXPECT_EQ(s.found, s.objects);
    EXPECT_EQ(s.false_objects, 0u);
  }
}

TEST(SegmentSyntheticScenes, ObjectsApartOnATable) { expect_every_object(synth::SceneLayout::random, 3); }
TEST(SegmentSyntheticScenes, ObjectsInARow) { expect_every_object(synth::SceneLayout::row, 3); }
// Stacks of three boxes, each turned at random on the one below (stacked seeds 1-10): what the
// default segmentation finds, and how many boxes each of `without` (rules turned off) finds
// instead (each frame captured once).
struct StackCounts {
  std::size_t objects = 0, found = 0, false_objects = 0;
  std::vector<std::size_t> found_without;
  std::string detail;
};

StackCounts stacks_of_three(const std::vector<config::SegmentConfig>& without) {
  StackCounts out;
  out.found_without.assign(without.size(), 0);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    synth::SceneRecipe recipe;
    recipe.layout = synth::SceneLayout::stacked;
    recipe.count = 3;
    recipe.seed = seed;
    const CapturedScene scene = capture_points(recipe, small_camera());
    const Scored s = score(scene, config::PipelineConfig{}.segment);
    out.objects += s.objects;
    out.found += s.found;
    out.false_objects += s.false_objects;
    for (std::size_t k = 0; k < without.size(); ++k)
      out.found_without[k] += score(scene, without[k]).found;
    out.detail += " seed " + std::to_string(seed) + ":" + s.detail;
  }
  return out;
}

// Boxes and cans lined up touching: where a box's top meets its neighbour's front at a step
// finer than the graph the junction looks convex, but the two faces reach their crease side by
// side (convex_segments: crease_overlap), and slivers along the step bridge nothing.
TEST(SegmentSyntheticScenes, TouchingObjects) { expect_every_object(synth::SceneLayout::touching, 2); }
// DISABLED (issue 10, left): seed 4: the table is not taken for structure: its plane is found (21
// times the stack's footprint) but only 2 of the stack's contact nodes, not
// structure_min_standing (10), have table beyond them in all four in-plane directions
// (structure_planes); it comes out as a false object. Seed 1 passes since the concave cuts below.
TEST(SegmentSyntheticScenes, DISABLED_BoxOnBox) { expect_every_object(synth::SceneLayout::stacked, 2); }
// Stacks of three boxes, each turned at random on the one below: where an upper box's face is
// turned only 20-45 degrees from the face below it, the two faces' normals blur into each other
// over the normal window and grow one patch; the crease test (segment.crease_degrees) cuts them,
// and a patch of offset flat pieces is split into them (segment.piece_*, planar_pieces.hpp). Each
// rule alone finds more boxes than neither. Measured (320 x 240 frames): both 27 of 30, creases
// alone 24, pieces alone 28, neither 21.
TEST(SegmentSyntheticScenes, StacksOfThreeTurnedBoxes) {
  config::SegmentConfig neither = config::PipelineConfig{}.segment;
  neither.crease_degrees = 0.0;
  neither.piece_max_planes = 0;
  config::SegmentConfig only_creases = config::PipelineConfig{}.segment, only_pieces = only_creases;
  only_creases.piece_max_planes = 0;
  only_pieces.crease_degrees = 0.0;
  const StackCounts s = stacks_of_three({neither, only_creases, only_pieces});
  const std::size_t none = s.found_without[0], creases = s.found_without[1],
                    pieces = s.found_without[2];
  SCOPED_TRACE(s.detail + " (found " + std::to_string(s.found) + ", creases alone " +
               std::to_string(creases) + ", pieces alone " + std::to_string(pieces) + ", neither " +
               std::to_string(none) + ")");
  EXPECT_GE(3 * s.found, 2 * s.objects) << "at least two thirds of the boxes, each one segment (IoU >= 0.8)";
  EXPECT_GT(creases, none);
  EXPECT_GT(pieces, none);
  EXPECT_GT(s.found, none);
  EXPECT_EQ(s.false_objects, 0u);
}
// Stacks of three boxes (the frames of StacksOfThreeTurnedBoxes): the concave cuts find more of
// them and make no false object.
TEST(SegmentSyntheticScenes, ConcaveCutsSeparateStackedBoxes) {
  config::SegmentConfig without_cuts = config::PipelineConfig{}.segment;
  without_cuts.concave_cut_band = 0.0;
  const StackCounts s = stacks_of_three({without_cuts});
  SCOPED_TRACE(s.detail + " (found " + std::to_string(s.found) + ", without cuts " +
               std::to_string(s.found_without[0]) + ")");
  // Measured: 27 of 30 with the cuts, 25 without.
  EXPECT_GE(s.found, 25u);
  EXPECT_GT(s.found, s.found_without[0]);
  EXPECT_EQ(s.false_objects, 0u);
}

// Stacks of three turned boxes at 640 x 480 (stacked seeds 1, 16 and 40): a box turned on a
// slightly larger one shows a strip of the lower top in front of it, which meets its front
// concavely, but where the strip runs out the two fronts, about 10 degrees apart, grow one flat
// patch within the cut's band, and a flat patch through the cut stopped it: the two boxes were one
// segment. Spread off its plane twice as far as its two pieces off theirs
// (segment.concave_cut_kink_ratio) it is two faces at a kink and is split. Measured: 9 of 9 boxes
// (IoU >= 0.8), 3 without the rule.
TEST(SegmentSyntheticScenes, FrontsJoinedAtAKinkAreCutAlongTheLowerTop) {
  config::SegmentConfig without_kinks = config::PipelineConfig{}.segment;
  without_kinks.concave_cut_kink_ratio = 0.0;
  std::size_t objects = 0, found = 0, found_without = 0, false_objects = 0;
  std::string detail;
  for (std::uint64_t seed : {1, 16, 40}) {
    synth::SceneRecipe recipe;
    recipe.layout = synth::SceneLayout::stacked;
    recipe.count = 3;
    recipe.seed = seed;
    const CapturedScene scene = capture_points(recipe, synth::CaptureOptions{});
    const Scored s = score(scene, config::PipelineConfig{}.segment);
    objects += s.objects;
    found += s.found;
    false_objects += s.false_objects;
    found_without += score(scene, without_kinks).found;
    detail += " seed " + std::to_string(seed) + ":" + s.detail;
  }
  SCOPED_TRACE(detail + " (found " + std::to_string(found) + ", without the rule " +
               std::to_string(found_without) + ")");
  EXPECT_EQ(found, objects);
  EXPECT_LT(found_without, found);
  EXPECT_EQ(false_objects, 0u);
}

// Boxes stacked under a Kinect's faults (stacked seeds 2 and 16, three boxes, 640 x 480: depth
// noise 0.0019 z^2, disparity steps, projector shadows, flying pixels). The lower top's strip in
// front of an upper box meets its front concavely, and the cut along the strip's plane was stopped
// where the strip runs out: there the upper front meets the lower box's sides at a convex edge, a
// short one (41 graph edges against the strip's 107 in seed 16). A convex edge stops the cut only
// when it is at least as long as the concave junction cut (a can's rim against where a taller can
// touches its lid). Measured: 4 of 6 boxes (IoU >= 0.8: seed 2's three and seed 16's bottom one),
// no false segment; 1 of 6 when every convex edge stopped the cut. Seed 16's two upper boxes (the
// top one mostly hidden) are still one segment.
TEST(SegmentSyntheticScenes, AShortConvexEdgeWhereAStripRunsOutDoesNotStopTheCut) {
  const synth::CaptureOptions kinect = testing::kinect_faults();
  std::size_t objects = 0, found = 0, false_objects = 0;
  std::string detail;
  for (std::uint64_t seed : {2, 16}) {
    synth::SceneRecipe recipe;
    recipe.layout = synth::SceneLayout::stacked;
    recipe.count = 3;
    recipe.seed = seed;
    const Scored s = score(recipe, config::PipelineConfig{}.segment, kinect);
    objects += s.objects;
    found += s.found;
    false_objects += s.false_objects;
    detail += " seed " + std::to_string(seed) + ":" + s.detail;
  }
  SCOPED_TRACE(detail);
  EXPECT_EQ(objects, 6u);
  EXPECT_GE(found, 4u);
  EXPECT_EQ(false_objects, 0u);
}

// Objects touching in a row (touching seeds 14 and 25): where two solids' tops are level (two
// cans' lids, side by side) the two flat patches touch along a few edges, and joined there
// they made one segment of two or three objects; one face parted by a seam meets itself along
// the seam's length (segment.flat_junction_length). Every object found; with the rule off, a
// third of them.
TEST(SegmentSyntheticScenes, LevelTopsTouchingAtAPointStayApart) {
  config::SegmentConfig off = config::PipelineConfig{}.segment;
  off.flat_junction_length = 0.0;
  for (std::uint64_t seed : {14, 25}) {
    synth::SceneRecipe recipe;
    recipe.layout = synth::SceneLayout::touching;
    recipe.count = 3;
    recipe.seed = seed;
    const Scored with = score(recipe), without = score(recipe, off);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": with" + with.detail + "; without" + without.detail);
    EXPECT_EQ(with.found, with.objects);
    EXPECT_EQ(with.false_objects, 0u);
    EXPECT_LT(without.found, with.found);
  }
}

// Three objects touching near the table's far edge (touching seeds 2 and 7 of cloudshape-synth
// scene): their shadows cut the table behind them off from the part in front; the table beyond
// a shadow still shows that the table surrounds what stands on it, so no part of it is an object.
TEST(SegmentSyntheticScenes, TheTableBeyondTheObjectsShadowsIsTableToo) {
  for (std::uint64_t seed : {2, 7}) {
    synth::SceneRecipe recipe;
    recipe.layout = synth::SceneLayout::touching;
    recipe.count = 3;
    recipe.seed = seed;
    const Scored s = score(recipe);
    SCOPED_TRACE("touching seed " + std::to_string(seed) + ":" + s.detail);
    EXPECT_EQ(s.found, s.objects);
    EXPECT_EQ(s.false_objects, 0u);
  }
}
TEST(SegmentSyntheticScenes, ObjectsAgainstAWall) { expect_every_object(synth::SceneLayout::wall, 2); }

// Boxes under a Kinect's faults (640 x 480: depth noise 0.0019 z^2, disparity steps, projector
// shadows, flying pixels) whose face the search for structure took for a wall or a table: a row of
// three touching boxes (touching seed 4) whose middle one stands 3 cm out of the plane of its
// neighbours' fronts, so that it stands inside that plane, and two stacks of two (stacked seeds 24
// and 27) whose lower box's face reaches four times beyond the upper box's contact with it. The
// surface joined to such a face goes back behind it as deep as its box (measured over the
// Kinect-noise frames and stacks: 0.37-1.0 of the face's width; a table's edge 0.010-0.014 of the
// table's in mosd_learn), so it is no structure
// (segment.structure_max_behind): every box one segment. Without the test, 3 of the 7.
TEST(SegmentSyntheticScenes, ABoxsFaceWithItsBoxBehindItIsNoStructure) {
  const synth::CaptureOptions kinect = testing::kinect_faults();
  config::SegmentConfig without = config::PipelineConfig{}.segment;
  without.structure_max_behind = 1e9;
  std::size_t objects = 0, found = 0, found_without = 0, false_objects = 0;
  std::string detail;
  for (const auto& [layout, count, seed] : {std::tuple{synth::SceneLayout::touching, 3, 4},
                                            std::tuple{synth::SceneLayout::stacked, 2, 24},
                                            std::tuple{synth::SceneLayout::stacked, 2, 27}}) {
    synth::SceneRecipe recipe;
    recipe.layout = layout;
    recipe.count = static_cast<std::size_t>(count);
    recipe.seed = static_cast<std::uint64_t>(seed);
    const CapturedScene scene = capture_points(recipe, kinect);
    const Scored s = score(scene, config::PipelineConfig{}.segment);
    objects += s.objects;
    found += s.found;
    false_objects += s.false_objects;
    found_without += score(scene, without).found;
    detail += " " + synth::to_string(layout) + " seed " + std::to_string(seed) + ":" + s.detail;
  }
  SCOPED_TRACE(detail + " (without the test: " + std::to_string(found_without) + ")");
  EXPECT_EQ(objects, 7u);
  EXPECT_EQ(found, objects);
  EXPECT_EQ(false_objects, 0u);
  EXPECT_LT(found_without, found);
}

// A kitchen counter against a wall: a box 1.2 x 0.6 x 0.9 m on the floor whose top carries a box
// and a can, seen from 1.2 m in front of it and above, so that its front goes down behind its top
// deeper than the counter is wide (0.9 m against 0.6 m: segment.structure_max_behind is 0.25 of
// it). The first support found is the scene's whatever is behind it (the behind-test judges later
// ones, the faces of what stands on it): the top is structure (none without that rule) and each
// object on it one segment.
TEST(SegmentSyntheticScenes, ACountersTopIsStructureThoughItsFrontGoesDownBehindIt) {
  synth::Scene scene;
  synth::SceneRectangle floor;
  floor.kind = "plane";
  floor.half_u = floor.half_v = 3.0;
  scene.structure.push_back(floor);
  synth::SceneRectangle wall;
  wall.kind = "wall";
  wall.center = Eigen::Vector3d(0, 0.3, 1.5);
  wall.u = Eigen::Vector3d::UnitX();
  wall.v = -Eigen::Vector3d::UnitZ();
  wall.half_u = 3.0;
  wall.half_v = 1.5;
  wall.label = 2;
  scene.structure.push_back(wall);
  synth::Pose counter_pose, box_pose, can_pose;
  counter_pose.center = Eigen::Vector3d(0, 0, 0.45);
  box_pose.center = Eigen::Vector3d(-0.15, 0.0, 0.95);
  can_pose.center = Eigen::Vector3d(0.2, -0.05, 0.96);
  can_pose.axes = Eigen::AngleAxisd(-1.5707963267948966, Eigen::Vector3d::UnitY())
                      .toRotationMatrix()
                      .transpose();
  scene.objects.push_back(
      {synth::make_solid(synth::ShapeKind::box, {1.2, 0.6, 0.9}, counter_pose), 5});
  scene.objects.push_back(
      {synth::make_solid(synth::ShapeKind::box, {0.22, 0.15, 0.1}, box_pose), 20});
  scene.objects.push_back(
      {synth::make_solid(synth::ShapeKind::cylinder, {0.04, 0.12}, can_pose), 30});
  synth::DepthCamera camera;
  camera.width = 320;
  camera.height = 240;
  std::mt19937_64 rng(1);
  const synth::SensorPose pose = synth::look_at({0.3, -1.2, 1.7}, {0.0, 0.0, 0.9});
  const CapturedScene captured = captured_points(synth::render(scene, camera, pose, rng));
  const SceneSegmentation s =
      segment_scene(captured.points, captured.grid, config::PipelineConfig{}.segment);
  // The counter's top in the camera's frame: normal the world's up, 0.8 m below the camera.
  const Eigen::Vector3d up = pose.axes * Eigen::Vector3d::UnitZ();
  bool top = false;
  for (const StructurePlane& p : s.structure)
    top = top || (std::abs(p.plane.normal.dot(up)) > 0.99 &&
                  std::abs(std::abs(p.plane.offset) - 0.8) < 0.02);
  EXPECT_TRUE(top) << "the counter's top is structure (" << s.structure.size() << " planes)";
  const Scored scored = score(captured, config::PipelineConfig{}.segment);
  SCOPED_TRACE(scored.detail);
  EXPECT_EQ(scored.objects, 2u);
  EXPECT_EQ(scored.found, 2u);
}

// Stacks of three boxes seen at 640 x 480 with independent depth noise of a Kinect's size (0.0019
// z^2: 2.7 mm at 1.2 m, more than the 2 mm between pixels there): a normal from 5 x 5 neighbouring
// pixels tilted by up to 20 degrees, the table's nodes did not agree on a plane, and the table with
// the stack on it came out as objects in 4 of these 5 frames. Now each normal's window spreads its
// samples until the noise tilts it by at most half of segment.smooth_degrees: no segment is mostly
// table, and each frame keeps a box whole (the other two are often one segment, as in these frames
// without noise).
TEST(SegmentSyntheticScenes, IndependentDepthNoiseLeavesTheTableOut) {
  synth::CaptureOptions options;
  options.depth_noise = 0.0019;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    synth::SceneRecipe recipe;
    recipe.layout = synth::SceneLayout::stacked;
    recipe.count = 3;
    recipe.seed = seed;
    const Scored s = score(recipe, config::PipelineConfig{}.segment, options);
    SCOPED_TRACE("stacked seed " + std::to_string(seed) + ":" + s.detail);
    EXPECT_EQ(s.false_objects, 0u);
    EXPECT_GE(s.found, 1u);
  }
}

// An organized frame of more points than one block of the parallel passes (the objects' points,
// the table's footprint left out of them) on two threads: the same objects, point for point.
TEST(SegmentSyntheticScenes, TwoThreadsGiveTheSameObjects) {
  synth::SceneRecipe recipe;
  recipe.layout = synth::SceneLayout::touching;
  recipe.count = 3;
  recipe.seed = 1;
  synth::CaptureOptions options;
  options.width = 640;
  options.height = 480;
  const CapturedScene scene = capture_points(recipe, options);
  ASSERT_GT(scene.points.size(), 65536u);
  const config::SegmentConfig cfg = config::PipelineConfig{}.segment;
  parallel::ThreadPool pool(2);
  const SceneSegmentation one = segment_scene(scene.points, scene.grid, cfg);
  ASSERT_GE(one.objects.size(), 3u);
  EXPECT_EQ(one.objects, segment_scene(scene.points, scene.grid, cfg, &pool).objects);
}

}  // namespace
}  // namespace cloudshape::segment
