// An unorganized cloud is tried on a coarser graph first: a lone dense solid is segmented there,
// and anything with a support in view or more than one object is segmented as a scene, as before.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/stage_configs.hpp"
#include "segment/neighbour_graph.hpp"
#include "segment/segment_scene.hpp"
#include "box_surface.hpp"

namespace cloudshape::segment {
namespace {

// The surface of an axis-aligned box, `size`, lowest corner at `corner`, sampled at random.
PointList box_surface(const Eigen::Vector3d& size, const Eigen::Vector3d& corner, std::size_t n,
                      std::mt19937_64& rng) {
  return testing::box_surface(size, Eigen::Matrix3d::Identity(), corner, n, rng);
}

// A sphere's surface, radius r about c.
PointList sphere_surface(double r, const Eigen::Vector3d& c, std::size_t n, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  PointList pts;
  for (std::size_t i = 0; i < n; ++i) pts.push_back(c + r * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
  return pts;
}

config::SegmentConfig without_trial() {
  config::SegmentConfig cfg;
  cfg.isolated_target_nodes = 0;
  return cfg;
}

// A dense lone box (100 000 points) is one object of all its points, on a graph of about
// isolated_target_nodes nodes (within 30%, as the voxel budget's own test), a quarter of the
// scene budget's.
TEST(SegmentIsolatedTrial, ADenseLoneSolidIsSegmentedOnTheCoarserGraph) {
  std::mt19937_64 rng(1);
  const PointList box = box_surface({0.4, 0.3, 0.2}, {0.1, -0.2, 0.5}, 100000, rng);
  const config::SegmentConfig cfg;
  const auto [scene, coarse] = budget_voxels(box, cfg, cfg.isolated_target_nodes);
  ASSERT_GT(coarse, 1.5 * scene);  // dense enough for the trial to apply
  const SceneSegmentation s = segment_scene(box, GridLayout{}, cfg);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects.front().size(), box.size());
  const double target = static_cast<double>(cfg.isolated_target_nodes);
  EXPECT_NEAR(static_cast<double>(s.graph_nodes), target, 0.3 * target);
  EXPECT_TRUE(s.lone_solid);
  const SceneSegmentation as_scene = segment_scene(box, GridLayout{}, without_trial());
  EXPECT_GT(as_scene.graph_nodes, 3 * s.graph_nodes);
  ASSERT_EQ(as_scene.objects.size(), 1u);
  EXPECT_EQ(as_scene.objects.front().size(), box.size());
}

// A sparse lone box (10 000 points: the isolated budget coarsens nothing) is tried on the scene's
// own graph: one object of all its points, the same graph and objects as without the trial, but
// known for a lone solid (no structure removal, no finer remainder graph). On a table it is a
// scene.
TEST(SegmentIsolatedTrial, ASparseLoneSolidIsTriedOnTheScenesOwnGraph) {
  std::mt19937_64 rng(7);
  const PointList box = box_surface({0.4, 0.3, 0.2}, {0.1, -0.2, 0.5}, 10000, rng);
  const config::SegmentConfig cfg;
  const auto [scene, coarse] = budget_voxels(box, cfg, cfg.isolated_target_nodes);
  ASSERT_EQ(coarse, scene);  // too sparse for a coarser trial graph
  const SceneSegmentation s = segment_scene(box, GridLayout{}, cfg);
  EXPECT_TRUE(s.lone_solid);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects.front().size(), box.size());
  const SceneSegmentation as_scene = segment_scene(box, GridLayout{}, without_trial());
  EXPECT_FALSE(as_scene.lone_solid);
  EXPECT_EQ(as_scene.graph_nodes, s.graph_nodes);
  EXPECT_EQ(as_scene.objects, s.objects);

  PointList on_table = box_surface({0.4, 0.3, 0.2}, {0.0, 0.0, 0.0}, 6000, rng);
  std::uniform_real_distribution<double> u(-0.6, 1.0);
  for (int i = 0; i < 6000; ++i) on_table.emplace_back(u(rng), u(rng), 0.0);
  const auto [table_scene, table_coarse] = budget_voxels(on_table, cfg, cfg.isolated_target_nodes);
  ASSERT_EQ(table_coarse, table_scene);
  const SceneSegmentation table = segment_scene(on_table, GridLayout{}, cfg);
  EXPECT_FALSE(table.lone_solid);
  EXPECT_FALSE(table.structure.empty());
  EXPECT_EQ(table.objects, segment_scene(on_table, GridLayout{}, without_trial()).objects);
}

// A dense box on a table: the coarser graph holds a plane reaching far beyond what stands on it,
// so the cloud is a scene, segmented exactly as without the trial (same graph, same objects).
TEST(SegmentIsolatedTrial, ASupportInViewMakesAScene) {
  std::mt19937_64 rng(2);
  PointList cloud = box_surface({0.4, 0.3, 0.2}, {0.0, 0.0, 0.0}, 60000, rng);
  std::uniform_real_distribution<double> u(-1.0, 1.4);
  while (cloud.size() < 160000) {
    const Point p(u(rng), u(rng), 0.0);
    if (p.x() < 0.0 || p.x() > 0.4 || p.y() < 0.0 || p.y() > 0.3) cloud.push_back(p);
  }
  const config::SegmentConfig cfg;
  const auto [scene, coarse] = budget_voxels(cloud, cfg, cfg.isolated_target_nodes);
  ASSERT_GT(coarse, 1.5 * scene);
  const SceneSegmentation s = segment_scene(cloud, GridLayout{}, cfg);
  const SceneSegmentation as_scene = segment_scene(cloud, GridLayout{}, without_trial());
  ASSERT_FALSE(s.structure.empty());
  EXPECT_EQ(s.graph_nodes, as_scene.graph_nodes);
  EXPECT_EQ(s.objects, as_scene.objects);
  ASSERT_EQ(s.objects.size(), 1u);
  // The scene's points go to their objects in blocks on two threads: the same lists.
  parallel::ThreadPool pool(2);
  EXPECT_EQ(segment_scene(cloud, GridLayout{}, cfg, &pool).objects, s.objects);
}

// A small ball beside a dense box: on the coarser graph the ball is a few nodes across and is
// left out (a sliver at that resolution), so the whole cloud is not one object there; as a scene
// the ball is an object of its own.
TEST(SegmentIsolatedTrial, ASmallSolidBesideADenseOneMakesAScene) {
  std::mt19937_64 rng(3);
  PointList cloud = box_surface({3.0, 2.0, 1.0}, {-1.5, -1.0, -0.5}, 30000, rng);
  const PointList ball = sphere_surface(0.25, {0.0, 4.0, 0.0}, 1500, rng);
  cloud.insert(cloud.end(), ball.begin(), ball.end());
  const config::SegmentConfig cfg;
  const auto [scene, coarse] = budget_voxels(cloud, cfg, cfg.isolated_target_nodes);
  ASSERT_GT(coarse, 1.5 * scene);
  const SceneSegmentation s = segment_scene(cloud, GridLayout{}, cfg);
  const SceneSegmentation as_scene = segment_scene(cloud, GridLayout{}, without_trial());
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[1].size(), ball.size());
  EXPECT_EQ(s.graph_nodes, as_scene.graph_nodes);
  EXPECT_EQ(s.objects, as_scene.objects);
}

// A small sparse ball 0.3 m beside a dense box: on the coarser graph it is left out (a few
// nodes), and the 180 points left out are more than cfg.min_object_nodes, so the cloud is a
// scene: the ball is an object of its own, as without the trial.
TEST(SegmentIsolatedTrial, ASmallSparseSolidBesideADenseOneIsKept) {
  std::mt19937_64 rng(4);
  PointList cloud = box_surface({0.4, 0.3, 0.2}, {0.0, 0.0, 0.0}, 100000, rng);
  const PointList ball = sphere_surface(0.025, {0.2, 0.65, 0.1}, 180, rng);
  cloud.insert(cloud.end(), ball.begin(), ball.end());
  const config::SegmentConfig cfg;
  const SceneSegmentation s = segment_scene(cloud, GridLayout{}, cfg);
  const SceneSegmentation as_scene = segment_scene(cloud, GridLayout{}, without_trial());
  ASSERT_EQ(as_scene.objects.size(), 2u);
  EXPECT_EQ(s.objects, as_scene.objects);
}

// Two small balls 10 m apart, sparse (no coarser graph to try): both found, each whole. The
// structure search removes nothing, and what it leaves is still gridded at its own resolution
// (at the scene's voxel each ball is a few nodes).
TEST(SegmentIsolatedTrial, TwoSmallSolidsFarApartAreBothFound) {
  std::mt19937_64 rng(5);
  PointList cloud = sphere_surface(0.05, {0.0, 0.0, 0.0}, 2000, rng);
  const PointList other = sphere_surface(0.05, {10.0, 0.0, 0.0}, 2000, rng);
  cloud.insert(cloud.end(), other.begin(), other.end());
  const SceneSegmentation s = segment_scene(cloud, GridLayout{}, config::SegmentConfig{});
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].size(), 2000u);
  EXPECT_EQ(s.objects[1].size(), 2000u);
}

// The trial and its segmentation on two threads: the same objects as on one.
TEST(SegmentIsolatedTrial, AnyThreadCountGivesTheSameObjects) {
  std::mt19937_64 rng(6);
  PointList cloud = box_surface({0.4, 0.3, 0.2}, {0.1, -0.2, 0.5}, 100000, rng);
  const PointList ball = sphere_surface(0.025, {0.3, 0.45, 0.6}, 180, rng);
  cloud.insert(cloud.end(), ball.begin(), ball.end());
  parallel::ThreadPool pool(2);
  const config::SegmentConfig cfg;
  const PointList lone(cloud.begin(), cloud.begin() + 100000);
  EXPECT_EQ(segment_scene(lone, GridLayout{}, cfg).objects, segment_scene(lone, GridLayout{}, cfg, &pool).objects);
  EXPECT_EQ(segment_scene(cloud, GridLayout{}, cfg).objects, segment_scene(cloud, GridLayout{}, cfg, &pool).objects);
}

}  // namespace
}  // namespace cloudshape::segment
