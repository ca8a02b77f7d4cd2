// Structure versus a solid's own face: a table under objects is removed, the largest face of a
// lone solid (a box, a cone's base, a single view's front face) is not.
#include <gtest/gtest.h>

#include <random>

#include "config/pipeline_config.hpp"
#include "segment/segment_scene.hpp"
#include "synth/ground_truth.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape::segment {
namespace {

synth::Pose at(double x, double y, double z) {
  synth::Pose p;
  p.center = Eigen::Vector3d(x, y, z);
  return p;
}

synth::Pose standing_on_cap(double x, double y, double z) {
  synth::Pose p = at(x, y, z);  // axis (local x) up
  p.axes = Eigen::AngleAxisd(-1.5707963267948966, Eigen::Vector3d::UnitY()).toRotationMatrix().transpose();
  return p;
}

PointList cloud_of(const std::vector<synth::SolidSpec>& solids, std::size_t points, std::uint64_t seed,
                   std::optional<Eigen::Vector3d> view = std::nullopt) {
  synth::CloudOptions opts;
  opts.points = points;
  opts.view = view;
  return synth::make_synthetic_cloud(solids, opts, seed).points;
}

// A table top of `size` x `size` at z = 0 with the footprints of the solids left out.
void add_table(PointList& points, double size, std::size_t count, std::uint64_t seed,
               const std::vector<std::pair<Point, double>>& holes) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-size / 2, size / 2);
  for (std::size_t i = 0; i < count; ++i) {
    const Point p(u(rng), u(rng), 0.0);
    bool hidden = false;
    for (const auto& [centre, radius] : holes) hidden = hidden || (p - centre).norm() < radius;
    if (!hidden) points.push_back(p);
  }
}

const config::SegmentConfig kCfg = config::PipelineConfig{}.segment;

TEST(SegmentStructure, ATableUnderObjectsIsStructure) {
  PointList points = cloud_of({synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, at(0, 0, 0.5)),
                               synth::make_solid(synth::ShapeKind::cylinder, {0.8, 2.0}, standing_on_cap(4, 1, 1))},
                              20000, 12, Eigen::Vector3d(2, -12, 10));
  add_table(points, 14.0, 30000, 13, {{Point(0, 0, 0), 1.8}, {Point(4, 1, 0), 0.8}});
  const SceneSegmentation s = segment_scene(points, GridLayout{}, kCfg);
  ASSERT_EQ(s.structure.size(), 1u);
  EXPECT_GT(std::abs(s.structure[0].plane.normal.z()), 0.999);
  EXPECT_GT(s.structure[0].plane.normal.z(), 0.0) << "normal towards what stands on it";
  EXPECT_EQ(s.objects.size(), 2u);
}

TEST(SegmentStructure, MillimetreTableBehavesLikeAMetreTable) {
  for (double unit : {1.0, 1000.0}) {
    PointList points = cloud_of({synth::make_solid(synth::ShapeKind::box, {3 * unit, 2 * unit, unit},
                                                   at(0, 0, 0.5 * unit))},
                                15000, 21, Eigen::Vector3d(2 * unit, -12 * unit, 10 * unit));
    PointList table;
    add_table(table, 14.0, 30000, 22, {{Point(0, 0, 0), 1.8}});
    for (const Point& p : table) points.push_back(p * unit);
    const SceneSegmentation s = segment_scene(points, GridLayout{}, kCfg);
    EXPECT_EQ(s.structure.size(), 1u) << "unit " << unit;
    EXPECT_EQ(s.objects.size(), 1u) << "unit " << unit;
  }
}

TEST(SegmentStructure, ASolidsOwnLargestFaceIsNotStructure) {
  const std::vector<std::pair<const char*, synth::SolidSpec>> solids = {
      {"flat box", synth::make_solid(synth::ShapeKind::box, {4, 3, 0.5}, at(0, 0, 0))},
      {"flat cone", synth::make_solid(synth::ShapeKind::cone, {2.0, 0.6}, standing_on_cap(0, 0, 0))},
      {"squat cylinder", synth::make_solid(synth::ShapeKind::cylinder, {2.0, 0.5}, standing_on_cap(0, 0, 0))},
  };
  for (const auto& [name, solid] : solids) {
    for (std::uint64_t seed : {1, 2, 3}) {
      const PointList whole = cloud_of({solid}, 8000, seed);
      const SceneSegmentation s = segment_scene(whole, GridLayout{}, kCfg);
      EXPECT_TRUE(s.structure.empty()) << name << " seed " << seed;
      ASSERT_EQ(s.objects.size(), 1u) << name << " seed " << seed;
      EXPECT_EQ(s.objects[0].size(), whole.size()) << name << " seed " << seed;
      // Seen from above at a slant: the big top face has the sides behind it.
      const PointList view = cloud_of({solid}, 8000, seed, Eigen::Vector3d(3, -4, 6));
      EXPECT_TRUE(segment_scene(view, GridLayout{}, kCfg).structure.empty()) << name << " view, seed " << seed;
    }
  }
}

// A cone seen from below its base at a slant: the base disc and a crescent of the side beyond
// its rim. The side leans over the base, so its nodes near the base lie above the base's inside;
// where it meets the base is the base's edge, as for any solid's face (the accuracy condition
// single_view lost such bases as tables and named the crescent a cylinder).
TEST(SegmentStructure, AConesBaseSeenFromBelowIsNotStructure) {
  const std::vector<std::pair<double, double>> cones = {{1.0, 0.73}, {1.0, 1.0}, {1.0, 1.86}};  // radius, height
  const std::vector<Eigen::Vector3d> cameras = {{3, -4, -3}, {-2, 3, -4}, {4, 1, -2.5}};
  for (const auto& [radius, height] : cones) {
    const auto cone = synth::make_solid(synth::ShapeKind::cone, {radius, height}, standing_on_cap(0, 0, 0));
    for (std::size_t k = 0; k < cameras.size(); ++k) {
      const PointList view = cloud_of({cone}, 30000, 11 + k, cameras[k]);
      const SceneSegmentation s = segment_scene(view, GridLayout{}, kCfg);
      SCOPED_TRACE("cone h " + std::to_string(height) + " camera " + std::to_string(k));
      EXPECT_TRUE(s.structure.empty());
      ASSERT_EQ(s.objects.size(), 1u);
      EXPECT_GE(static_cast<double>(s.objects[0].size()), 0.95 * static_cast<double>(view.size()));  // silhouette slivers aside
    }
  }
}

}  // namespace
}  // namespace cloudshape::segment
