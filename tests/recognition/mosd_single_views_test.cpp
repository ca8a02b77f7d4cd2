// Real Kinect single views (shared/data/real/mosd_learn, SOURCES.md): each ground-truth object of
// the 45 frames through the per-object stages, named right per category, and cans' radii.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <string>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "mosd_frames.hpp"
#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/preprocess.hpp"
#include "pipeline/solve.hpp"

namespace cloudshape {
namespace {

using mosd::data_missing;
using mosd::frame_path;
using mosd::kDir;

// SOURCES.md: label / 10 is the object (labels >= 20); groups under 50 points are ignored.
std::map<int, PointList> ground_truth_objects(const io::CloudFile& file) {
  std::map<int, PointList> groups;
  for (std::size_t i = 0; i < file.points.size(); ++i)
    if (file.labels[i] >= 20) groups[static_cast<int>(file.labels[i] / 10)].push_back(file.points[i]);
  for (auto it = groups.begin(); it != groups.end();)
    it = it->second.size() < 50 ? groups.erase(it) : std::next(it);
  return groups;
}

// The stages recognize_cloud runs on each object; the frames are in the Kinect's frame (sensor at
// the origin), which recognize_cloud knows from their grid.
pipeline::ObjectResult recognize_object(const PointList& raw, const config::PipelineConfig& cfg) {
  const auto pre = pipeline::preprocess_cloud(raw, cfg.preprocess);
  const auto planes = pipeline::segment_planes(pre.points, pre.resolution, cfg.planes);
  const auto kp = pipeline::find_keypoints(pre.points, planes, pre.resolution, cfg.keypoints);
  const auto cls = pipeline::classify_cloud(pre.points, planes, kp, pre.resolution, cfg.classify);
  return pipeline::solve_object(pre.points, planes, kp, cls, pre.resolution, cfg.solve, nullptr, Point::Zero());
}

std::string category(int frame) {
  return frame <= 16 ? "boxes" : frame <= 24 ? "stacked" : frame <= 32 ? "occluded" : "cylinders";
}

bool right_shape(const std::string& cat, const std::string& shape) {
  if (cat == "cylinders") return shape == "cylinder";
  if (cat == "occluded") return shape == "box" || shape == "cylinder";
  return shape == "box";
}

// Measured (config/pipeline.yaml at this commit): boxes 38/38, stacked 20/20, occluded 16/16,
// cylinders 29/38 before the container and side-refinement fixes; each floor is a few points below.
TEST(MosdSingleViews, GroundTruthObjectsNamedRightPerCategory) {
  if (data_missing()) GTEST_SKIP() << kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  std::map<std::string, std::pair<int, int>> tally;  // right, all
  for (int frame = 0; frame <= 44; ++frame) {
    const auto file = io::read_cloud(frame_path(frame));
    ASSERT_EQ(file.labels.size(), file.points.size()) << frame;
    for (const auto& [id, points] : ground_truth_objects(file)) {
      const auto r = recognize_object(points, cfg);
      const bool right = right_shape(category(frame), r.shape);
      tally[category(frame)].first += right ? 1 : 0;
      ++tally[category(frame)].second;
      if (right) {
        EXPECT_TRUE(r.partial) << "learn" << frame << " object " << id << ": a single view";
      }
    }
  }
  const std::map<std::string, double> floor = {
      {"boxes", 0.94}, {"stacked", 0.94}, {"occluded", 0.90}, {"cylinders", 0.70}};
  for (const auto& [cat, min_share] : floor) {
    const auto [right, all] = tally[cat];
    ASSERT_GT(all, 0) << cat;
    EXPECT_GE(static_cast<double>(right) / all, min_share) << cat << ": " << right << "/" << all;
  }
}

// A lid is a uniform disc: its points' mean squared distance from its centroid is R^2 / 2. The
// lid is found here by a plain RANSAC plane (3 mm, the Kinect's depth step at ~1 m), apart from
// the pipeline's planes and outlines.
double lid_disc_radius(const PointList& points) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::size_t> pick(0, points.size() - 1);
  std::vector<std::size_t> best;
  for (int it = 0; it < 300; ++it) {
    const Point a = points[pick(rng)], b = points[pick(rng)], c = points[pick(rng)];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() < 1e-12) continue;
    const Eigen::Vector3d u = n.normalized();
    std::vector<std::size_t> in;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (std::abs(u.dot(points[i] - a)) < 0.003) in.push_back(i);
    if (in.size() > best.size()) best = std::move(in);
  }
  Point centroid = Point::Zero();
  for (std::size_t i : best) centroid += points[i];
  centroid /= static_cast<double>(best.size());
  double sum = 0.0;
  for (std::size_t i : best) sum += (points[i] - centroid).squaredNorm();
  return std::sqrt(2.0 * sum / static_cast<double>(best.size()));
}

// Cans standing upright, lid and a band of side seen from above (cylinder category); tolerance 8%
// of the radius: the lid's rim and the Kinect's silhouette pixels move either estimate by a few mm.
TEST(MosdSingleViews, CanRadiusMatchesItsLidDisc) {
  if (data_missing()) GTEST_SKIP() << kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const std::vector<std::pair<int, int>> cans = {{33, 3}, {36, 2}, {40, 2}, {44, 2}};
  for (const auto& [frame, id] : cans) {
    const auto objects = ground_truth_objects(io::read_cloud(frame_path(frame)));
    ASSERT_TRUE(objects.count(id)) << "learn" << frame << " object " << id;
    const PointList& points = objects.at(id);
    const auto r = recognize_object(points, cfg);
    ASSERT_EQ(r.shape, "cylinder") << "learn" << frame << " object " << id;
    const double expected = lid_disc_radius(points);
    EXPECT_NEAR(r.dimensions.at(0).second, expected, 0.08 * expected)
        << "learn" << frame << " object " << id;
    EXPECT_TRUE(r.partial);
  }
}

// One bowl seen over its rim in four frames (cylinder category): its inside is concave towards
// the sensor, so it is the container's envelope cylinder, not a sphere. Its rim radius in each
// view within 8% of the four views' mean (silhouette pixels and the rim's wall thickness), its
// depth under its rim radius (a bowl is wider than deep), a single view.
TEST(MosdSingleViews, BowlSeenIntoIsOneCylinderInEveryView) {
  if (data_missing()) GTEST_SKIP() << kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const std::vector<std::pair<int, int>> views = {{33, 4}, {34, 4}, {35, 4}, {36, 3}};
  std::vector<double> radii, depths;
  for (const auto& [frame, id] : views) {
    const auto objects = ground_truth_objects(io::read_cloud(frame_path(frame)));
    ASSERT_TRUE(objects.count(id)) << "learn" << frame << " object " << id;
    const auto r = recognize_object(objects.at(id), cfg);
    ASSERT_EQ(r.shape, "cylinder") << "learn" << frame << " object " << id << ": " << r.reason;
    radii.push_back(r.dimensions.at(0).second);
    depths.push_back(r.dimensions.at(1).second);
    EXPECT_TRUE(r.partial) << "learn" << frame;
  }
  const auto mean = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m += x / static_cast<double>(v.size());
    return m;
  };
  const double radius = mean(radii), depth = mean(depths);
  for (std::size_t k = 0; k < radii.size(); ++k) {
    EXPECT_NEAR(radii[k], radius, 0.08 * radius) << "learn" << views[k].first;
    EXPECT_NEAR(depths[k], depth, 0.15 * depth) << "learn" << views[k].first;
  }
}

}  // namespace
}  // namespace cloudshape
