// Synthetic lidar frames (cloudshape-synth scene --layout lidar): a 0.25-0.35 m sphere on the
// ground among two walls, 32 rings, unorganized returns with 1 cm range noise. The sphere is
// found, from its own points at its own resolution (a floor over 10 seeds); frames of three solids
// name few of them wrongly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "config/pipeline_config.hpp"
#include "lidar_frames.hpp"
#include "pipeline/recognize.hpp"
#include "report_of_label.hpp"
#include "synth/ground_truth.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape {
namespace {

// Tolerance (issue 10): radius within 5%, centre within 10% of the radius, in at least 80% of the
// frames that see the sphere: today 8 of 10 (5 before the ground's points left the finer graph
// around the ball's foot; the misses, seeds 7 and 8, come out a frustum); the issue asks for every
// frame.
TEST(LidarScene, CalibrationSphereOnTheGroundAmongWalls) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  int seen = 0, found = 0;
  std::string misses;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const synth::SceneCapture capture = testing::lidar_capture(seed);
    const synth::SolidSpec& sphere = capture.scene.objects.front().solid;
    const double radius = synth::dimension(sphere, "radius");
    const Eigen::Vector3d centre = sphere.pose.center;
    PointList points;
    std::size_t on_sphere = 0;
    for (std::size_t i = 0; i < capture.image.points.size(); ++i) {
      if (!capture.image.points[i].allFinite()) continue;
      points.push_back(capture.image.points[i]);
      on_sphere += capture.image.labels[i] == capture.scene.objects.front().label ? 1 : 0;
    }
    if (on_sphere < 100) continue;  // the sphere below the lowest beam: nothing to find
    const auto result = pipeline::recognize_cloud(points, cfg, "lidar");
    ++seen;
    const auto nearest = std::min_element(result.objects.begin(), result.objects.end(), [&](const auto& a, const auto& b) {
      return (a.center - centre).norm() < (b.center - centre).norm();
    });
    const bool right = nearest != result.objects.end() && nearest->shape == "sphere" && !nearest->dimensions.empty() &&
                       std::abs(nearest->dimensions.front().second - radius) <= 0.05 * radius &&
                       (nearest->center - centre).norm() <= 0.1 * radius;
    found += right ? 1 : 0;
    if (!right) {
      misses += " seed " + std::to_string(seed) +
                (nearest == result.objects.end() ? std::string(": nothing") : ": " + nearest->shape);
    }
  }
  ASSERT_GE(seen, 5);
  EXPECT_GE(10 * found, 8 * seen) << found << " of " << seen << ";" << misses;
}

// Seed 15: a 0.26 m ball resting on the ground, its top a few coarse voxels above it. The ground
// seen from inside takes its parts apart from its connected one too (beyond shadows), but only
// within the noise the connected one shows, not its whole band: the ball keeps its top and is
// found (before, the top went with the ground, the rest of the ball made no object, and the
// nearest object was a scrap of ground 10 m away).
TEST(LidarScene, ABallRestingOnTheGroundKeepsItsTop) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const synth::SceneCapture capture = testing::lidar_capture(15);
  const synth::SolidSpec& sphere = capture.scene.objects.front().solid;
  const double radius = synth::dimension(sphere, "radius");
  PointList points;
  for (const Point& p : capture.image.points)
    if (p.allFinite()) points.push_back(p);
  const auto result = pipeline::recognize_cloud(points, cfg, "lidar");
  const auto nearest = std::min_element(result.objects.begin(), result.objects.end(), [&](const auto& a, const auto& b) {
    return (a.center - sphere.pose.center).norm() < (b.center - sphere.pose.center).norm();
  });
  ASSERT_NE(nearest, result.objects.end());
  EXPECT_EQ(nearest->shape, "sphere");
  ASSERT_FALSE(nearest->dimensions.empty());
  EXPECT_NEAR(nearest->dimensions.front().second, radius, 0.05 * radius);
  EXPECT_LE((nearest->center - sphere.pose.center).norm(), 0.1 * radius);
}

// The same frames without the sphere: ground and two walls are structure, and what they leave is
// no object the size of the scene (all of the frame as one object was once the answer when no
// segment was left: a 20 m box).
TEST(LidarScene, GroundAndWallsAloneGiveNoSceneSizedObject) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const synth::SceneCapture capture = testing::lidar_capture(seed);
    PointList points;
    for (std::size_t i = 0; i < capture.image.points.size(); ++i) {
      if (!capture.image.points[i].allFinite() || capture.image.labels[i] >= 20) continue;
      points.push_back(capture.image.points[i]);
    }
    const auto result = pipeline::recognize_cloud(points, cfg, "lidar");
    for (const auto& o : result.objects) {
      EXPECT_LT(o.extent.size.maxCoeff(), 3.0) << "seed " << seed << ": " << o.shape << " " << o.extent.size.transpose();
    }
  }
}

// A capture's returns (no-return pixels left out) and their truth labels.
void returns_of(const synth::SceneCapture& capture, PointList& points,
                std::vector<std::uint32_t>& labels) {
  for (std::size_t i = 0; i < capture.image.points.size(); ++i) {
    if (!capture.image.points[i].allFinite()) continue;
    points.push_back(capture.image.points[i]);
    labels.push_back(capture.image.labels[i]);
  }
}

// Frames of three solids (a sphere and two drawn from the six) on the ground among walls, seeds
// 1-30, 32 rings, 1 cm range noise: most objects on three to six rings. Each labelled object with
// 30 returns or more is judged by the reported object holding most of its returns.
struct ThreeSolidFrames {
  int right = 0;
  int wrong = 0;  // named, and not its shape
  std::string wrongs;
};

ThreeSolidFrames judge_three_solid_frames(const config::PipelineConfig& cfg) {
  ThreeSolidFrames out;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const synth::SceneCapture capture =
        testing::lidar_capture(seed, synth::CaptureOptions{}.rings, 3);
    PointList points;
    std::vector<std::uint32_t> labels;
    returns_of(capture, points, labels);
    std::map<std::uint32_t, std::size_t> returns;
    for (std::uint32_t label : labels) ++returns[label];
    const auto result = pipeline::recognize_cloud(points, cfg, "lidar");
    for (const auto& object : capture.scene.objects) {
      if (returns[object.label] < 30) continue;
      const pipeline::ObjectResult* holder =
          testing::report_of_label(result.objects, labels, object.label);
      if (!holder || holder->shape == "unknown") continue;
      const std::string truth = synth::to_string(object.solid.kind);
      if (holder->shape == truth) {
        ++out.right;
      } else {
        ++out.wrong;
        out.wrongs += " seed " + std::to_string(seed) + ": " + truth + " as " + holder->shape;
      }
    }
  }
  return out;
}

// On so few rings a wrong solid passes within inlier_distance of most points (a ring's spacing, far
// finer than the ranging noise, sets the resolution): 19 objects were named wrongly. A solid that
// leaves its points scattered by more than solve.scan_noise_ratio (3) times their noise along the
// rings is no answer, an object on fewer rings than solve.solid_min_scan_lines (5) is tried as a
// sphere only (on three or four a tetrahedron, prism, cylinder or ball passed for a box, cone or
// frustum), and a solid the sensor saw through is no answer either (below). Measured: 5 named
// wrongly, 41 right. Bounds: 7 wrong, 39 right.
TEST(LidarScene, FewSolidsNamedWronglyOnFewRings) {
  const ThreeSolidFrames judged =
      judge_three_solid_frames(config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML));
  EXPECT_LE(judged.wrong, 7) << judged.wrongs;
  EXPECT_GE(judged.right, 39);
}

// A lidar object's solid must stand where the sensor saw no free space
// (solve.free_space_max_share): on a few rings a fit is free between and beyond them, and the
// frame's rays beside and behind the object measure where it is not. Measured on the frames above:
// 5 named wrongly, 8 without the test (a 0.5 m ball for a can 0.35 m wide, boxes across a wall
// strip: 45-85% of their crossing rays return from beyond them); 41 right, 42 without (a cylinder
// of 0.43 m radius for one of 0.26, 45% of its rays through it). Bounds: 2 named wrongly fewer, at
// most 2 right fewer.
TEST(LidarScene, NoSolidIsNamedWhereTheSensorSawThroughIt) {
  auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const ThreeSolidFrames with = judge_three_solid_frames(cfg);
  cfg.solve.free_space_max_share = 0.0;
  const ThreeSolidFrames without = judge_three_solid_frames(cfg);
  EXPECT_LE(with.wrong + 2, without.wrong) << with.wrongs << " /" << without.wrongs;
  EXPECT_GE(with.right + 2, without.right);
}

// On a few rings a cone's tip lies between them, unseen: the points of seeds 45, 55 and 58's cones
// (on 6-8 rings, 3.3-3.9 m off) stop 20-45% of the cone's height short of it, and a frustum ending
// at the top ring explains them as well as the cone, so they were frustums. The rays say whether
// the tip is there: the frustum's cone lets none through, and is the answer
// (solve.free_space_max_share; off, all three are frustums again).
TEST(LidarScene, AConesTipBetweenTheRingsIsNoFrustumsTop) {
  auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const auto cone_named = [&](const config::PipelineConfig& c, std::uint64_t seed) {
    const synth::SceneCapture capture =
        testing::lidar_capture(seed, synth::CaptureOptions{}.rings, 3);
    PointList points;
    std::vector<std::uint32_t> labels;
    returns_of(capture, points, labels);
    const auto result = pipeline::recognize_cloud(points, c, "lidar");
    // The frame's cone the rings see most of.
    const synth::SceneObject* cone = nullptr;
    std::size_t most = 0;
    for (const auto& object : capture.scene.objects) {
      const auto returns =
          static_cast<std::size_t>(std::count(labels.begin(), labels.end(), object.label));
      if (synth::to_string(object.solid.kind) == "cone" && returns > most)
        cone = &object, most = returns;
    }
    if (cone == nullptr) return std::string("no cone in the frame");
    const pipeline::ObjectResult* holder =
        testing::report_of_label(result.objects, labels, cone->label);
    return holder ? holder->shape : std::string("nothing");
  };
  for (std::uint64_t seed : {45, 55, 58})
    EXPECT_EQ(cone_named(cfg, seed), "cone") << "seed " << seed;
  cfg.solve.free_space_max_share = 0.0;
  for (std::uint64_t seed : {45, 55, 58})
    EXPECT_EQ(cone_named(cfg, seed), "frustum") << "seed " << seed;
}

}  // namespace
}  // namespace cloudshape
