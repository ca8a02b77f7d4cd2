// An unorganized depth-camera frame (thinned to one point per voxel, so no pixel grid is left to
// recover) is seen from the origin: its normals face the camera and the depth image's rules
// separate what touches; a cloud written elsewhere, or a lone solid, is not taken for one.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <unordered_set>

#include "captured_scene.hpp"
#include "config/pipeline_config.hpp"
#include "segment/segment_scene.hpp"

namespace cloudshape::segment {
namespace {

// The first point of each voxel of `size`, moved by a hundredth of that off its pixel's ray.
CapturedScene thinned(const CapturedScene& scene, double size) {
  CapturedScene out;
  std::unordered_set<std::uint64_t> seen;
  for (std::size_t i = 0; i < scene.points.size(); ++i) {
    const Point& p = scene.points[i];
    const auto cell = [size](double v) {
      return static_cast<std::uint64_t>(std::floor(v / size) + 1e6);
    };
    if (!seen.insert(cell(p.x()) << 42 ^ cell(p.y()) << 21 ^ cell(p.z())).second) continue;
    out.points.push_back(p + 0.01 * size * Point(std::sin(1.7 * i), std::cos(2.3 * i), 0.0));
    out.labels.push_back(scene.labels[i]);
    ++out.size[scene.labels[i]];
  }
  return out;
}

// Objects found with at least 80% point overlap by a segment of their own.
int objects_found(const CapturedScene& scene, const SceneSegmentation& s) {
  std::map<std::uint32_t, double> best;
  for (const auto& object : s.objects) {
    std::map<std::uint32_t, std::size_t> votes;
    for (std::uint32_t i : object) ++votes[scene.labels[i]];
    for (const auto& [label, n] : votes) {
      const double iou =
          static_cast<double>(n) / static_cast<double>(object.size() + scene.size.at(label) - n);
      best[label] = std::max(best[label], iou);
    }
  }
  int found = 0;
  for (const auto& [label, size] : scene.size)
    found += label >= 20 && size >= 200 && best[label] >= 0.8 ? 1 : 0;
  return found;
}

CapturedScene stacked(std::uint64_t seed) {
  synth::SceneRecipe recipe;
  recipe.layout = synth::SceneLayout::stacked;
  recipe.count = 2;
  recipe.seed = seed;
  return thinned(capture_points(recipe, synth::CaptureOptions{}), 0.004);
}

// Two boxes stacked, seeds 1-4, thinned to 4 mm: 4 of their 8 boxes found apart (none as a voxel
// graph without a viewpoint, its normals turned outward from each part's centroid: every stack one
// object; with the camera's rules two stacks still come out whole).
TEST(CameraView, AThinnedFramesStackedBoxesComeApart) {
  const config::SegmentConfig cfg = config::PipelineConfig{}.segment;
  int found = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const CapturedScene scene = stacked(seed);
    const SceneSegmentation s = segment_scene(scene.points, GridLayout{}, cfg);
    EXPECT_TRUE(s.camera_view) << "seed " << seed;
    EXPECT_EQ(s.viewpoint.value_or(Point::Ones()), Point::Zero());
    EXPECT_EQ(s.scan_lines, std::vector<std::uint32_t>(s.objects.size(), 0));
    found += objects_found(scene, s);
  }
  EXPECT_GE(found, 3);
}

TEST(CameraView, NoCameraWhereTheOriginSeesNoSupportFromAbove) {
  const config::SegmentConfig cfg = config::PipelineConfig{}.segment;
  const CapturedScene scene = stacked(1);
  // Moved so that the origin lies between the boxes and the table (a world frame's origin).
  PointList moved = scene.points;
  Point centre = Point::Zero();
  for (const Point& p : moved) centre += p;
  centre /= static_cast<double>(moved.size());
  for (Point& p : moved) p -= Point(centre.x(), centre.y(), 0.0);
  PointList lifted = moved;
  for (Point& p : lifted) p.z() -= centre.z();
  EXPECT_FALSE(segment_scene(lifted, GridLayout{}, cfg).camera_view);
  // Behind the camera's plane: some points at z < 0.
  PointList behind = scene.points;
  for (Point& p : behind) p.z() -= centre.z() - 0.05;
  EXPECT_FALSE(segment_scene(behind, GridLayout{}, cfg).camera_view);
  // A lone solid in front of the camera: no support in view.
  PointList ball;
  for (int i = 0; i < 4000; ++i) {
    const double u = 2.0 * (i + 0.5) / 4000.0 - 1.0, phi = 2.399963 * i;
    const double r = std::sqrt(1.0 - u * u);
    ball.emplace_back(0.1 * r * std::cos(phi), 0.1 * r * std::sin(phi), 1.5 + 0.1 * u);
  }
  EXPECT_FALSE(segment_scene(ball, GridLayout{}, cfg).camera_view);
}

}  // namespace
}  // namespace cloudshape::segment
