// Unorganized clouds: each voxel node is the centroid of its points, neighbours are mutual, and
// each node's normal is that of its normal_neighbours nearest nodes (brute force, same tolerance).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "config/stage_configs.hpp"
#include "geometry/pca.hpp"
#include "geometry/voxel_grid.hpp"
#include "segment/detail/graph_moments.hpp"
#include "parallel/thread_pool.hpp"
#include "segment/neighbour_graph.hpp"
#include "box_surface.hpp"

namespace cloudshape::segment {
namespace {

// The surface of a tilted 40 x 30 x 20 box, sampled at random.
PointList tilted_box(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX())).matrix();
  return testing::box_surface({40.0, 30.0, 20.0}, turn, {5.0, -3.0, 2.0}, n, rng);
}

TEST(SegmentVoxelGraph, NodesAreTheCentroidsOfTheirPointsAndNeighboursAreMutual) {
  const PointList pts = tilted_box(30000, 1);
  const NeighbourGraph g = build_voxel_graph(pts, config::SegmentConfig{});
  ASSERT_GT(g.size(), 1000u);
  std::vector<Eigen::Vector3d> sum(g.size(), Eigen::Vector3d::Zero());
  std::vector<std::size_t> count(g.size(), 0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    ASSERT_LT(g.node_of_point[i], g.size());
    sum[g.node_of_point[i]] += pts[i];
    ++count[g.node_of_point[i]];
  }
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    ASSERT_GT(count[n], 0u);
    EXPECT_LT((sum[n] / static_cast<double>(count[n]) - g.nodes[n]).norm(), 1e-9);
    g.for_neighbours(n, [&](std::uint32_t m) {
      bool back = false;
      g.for_neighbours(m, [&](std::uint32_t o) { back = back || o == n; });
      EXPECT_TRUE(back) << n << " -> " << m;
    });
  }
}

TEST(SegmentVoxelGraph, NormalsAreThoseOfTheNearestNodes) {
  const config::SegmentConfig cfg;
  const PointList pts = tilted_box(30000, 2);
  const NeighbourGraph g = build_voxel_graph(pts, cfg);
  const auto k = static_cast<std::size_t>(cfg.normal_neighbours);
  ASSERT_GT(g.size(), k);
  std::vector<std::pair<double, std::uint32_t>> ranked;
  for (std::uint32_t n = 0; n < g.size(); n += 13) {
    ranked.clear();
    for (std::uint32_t m = 0; m < g.size(); ++m) ranked.emplace_back((g.nodes[m] - g.nodes[n]).squaredNorm(), m);
    std::partial_sort(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(k), ranked.end());
    std::vector<std::uint32_t> nearest;
    for (std::size_t j = 0; j < k; ++j) nearest.push_back(ranked[j].second);
    const geometry::Pca pca = geometry::compute_pca(g.nodes, nearest);
    // Same neighbours, so the same surface variation up to rounding (a neighbour more or less
    // near an edge moves it by far more), and the same normal where it is well defined (sign
    // aside: no viewpoint orients it).
    EXPECT_NEAR(g.curvature[n], pca.surface_variation(), 1e-7) << "node " << n;
    const Eigen::Vector3d l = pca.eigenvalues;
    if (l(1) - l(0) > 1e-3 * l(2)) {
      EXPECT_GT(std::abs(pca.eigenvectors.col(0).dot(g.normals[n])), 1.0 - 1e-6) << "node " << n;
    }
  }
}

// along_a_line answers as the eigenvalues alone do (its shortcut for a surface changes no
// answer): neighbourhoods from a line to a plane to a blob, spreads around the threshold.
TEST(SegmentVoxelGraph, LineTestAsTheEigenvaluesSay) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double kLine = 0.1;
  std::size_t on_line = 0, across = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Axis spreads 1, a, b: a around kLine on most trials, b up to a.
    const double a = trial % 3 == 0 ? unit(rng) : kLine * (0.5 + unit(rng));
    const double b = a * unit(rng);
    const Eigen::Matrix3d rot = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    const Point centre(gauss(rng) * 100.0, gauss(rng) * 100.0, gauss(rng) * 100.0);
    detail::Moments m;
    m.origin = centre;
    const int count = 3 + trial % 20;
    for (int i = 0; i < count; ++i) m.add(centre + rot * Eigen::Vector3d(gauss(rng), a * gauss(rng), b * gauss(rng)));
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(m.covariance(), Eigen::EigenvaluesOnly);
    const double major = eig.eigenvalues()(2);
    const double spread = major > 0.0 ? std::sqrt(std::max(0.0, eig.eigenvalues()(1)) / major) : 0.0;
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    const bool line = detail::along_a_line(m, kLine, direction);
    ASSERT_EQ(line, spread < kLine) << trial << " spread " << spread;
    on_line += line ? 1 : 0;
    across += line ? 0 : 1;
  }
  // Both answers were exercised, many times.
  EXPECT_GT(on_line, 2000u);
  EXPECT_GT(across, 2000u);
}

TEST(SegmentVoxelGraph, AGivenVoxelIsKeptWithoutANodeBudget) {
  config::SegmentConfig cfg;
  cfg.target_nodes = 50;  // a budget this small would grow any voxel fine enough for 30 000 points
  const PointList pts = tilted_box(30000, 3);
  const double voxel = 2.0 * finest_voxel(pts);
  ASSERT_GT(voxel, 0.0);
  const NeighbourGraph g = build_voxel_graph(pts, voxel, std::nullopt, cfg);
  ASSERT_GT(static_cast<double>(g.size()), 1.3 * static_cast<double>(cfg.target_nodes));
  // Two points share a node exactly when they share a voxel of that edge from the box's corner.
  const geometry::Bounds box = geometry::bounding_box(pts);
  std::map<std::array<std::int64_t, 3>, std::uint32_t> node_of_voxel;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d c = ((pts[i] - box.min) / voxel).array().floor();
    const std::array<std::int64_t, 3> key{static_cast<std::int64_t>(c.x()), static_cast<std::int64_t>(c.y()),
                                          static_cast<std::int64_t>(c.z())};
    const auto [it, added] = node_of_voxel.emplace(key, g.node_of_point[i]);
    EXPECT_EQ(it->second, g.node_of_point[i]) << "point " << i;
  }
  EXPECT_EQ(node_of_voxel.size(), g.size());
  // With the budget, the same voxel grows until at most 1.3 times the budget are occupied.
  EXPECT_LE(static_cast<double>(build_voxel_graph(pts, voxel, cfg.target_nodes, cfg).size()),
            1.3 * static_cast<double>(cfg.target_nodes));
}

// The voxels' nodes come from an array over the bounding box's voxels where it holds at most two
// a point, else from a hash map: one point far beyond the box's upper corner (the corner the
// voxels start from stays) sends the same cloud to the map, and every node of the cloud's own
// points is the same, with the same neighbours and normal.
TEST(SegmentVoxelGraph, TheVoxelArrayAndTheMapGiveTheSameGraph) {
  const config::SegmentConfig cfg;
  const PointList pts = tilted_box(30000, 5);
  const double voxel = 3.0 * finest_voxel(pts);
  const NeighbourGraph in_array = build_voxel_graph(pts, voxel, std::nullopt, cfg);
  PointList with_far = pts;
  with_far.push_back(geometry::bounding_box(pts).max + Eigen::Vector3d(1e4, 2e4, 3e4));
  const NeighbourGraph in_map = build_voxel_graph(with_far, voxel, std::nullopt, cfg);
  ASSERT_EQ(in_map.size(), in_array.size() + 1);
  for (std::size_t i = 0; i < pts.size(); ++i) ASSERT_EQ(in_map.node_of_point[i], in_array.node_of_point[i]) << i;
  for (std::uint32_t n = 0; n < in_array.size(); ++n) {
    EXPECT_EQ(in_map.nodes[n], in_array.nodes[n]) << "node " << n;
    EXPECT_EQ(in_map.normals[n], in_array.normals[n]) << "node " << n;
    std::vector<std::uint32_t> a, b;
    in_array.for_neighbours(n, [&](std::uint32_t m) { a.push_back(m); });
    in_map.for_neighbours(n, [&](std::uint32_t m) { b.push_back(m); });
    EXPECT_EQ(a, b) << "node " << n;
  }
}

// A large cloud's cells are worked out on the pool before the voxels are numbered: the same
// graph as without one, node for node.
TEST(SegmentVoxelGraph, APoolGivesTheSameGraph) {
  const config::SegmentConfig cfg;
  const PointList pts = tilted_box(250000, 6);
  const NeighbourGraph serial = build_voxel_graph(pts, cfg);
  for (std::size_t threads : {2u, 3u}) {
    parallel::ThreadPool pool(threads);
    const NeighbourGraph split = build_voxel_graph(pts, cfg, &pool);
    ASSERT_EQ(split.size(), serial.size()) << threads;
    EXPECT_EQ(split.node_of_point, serial.node_of_point) << threads;
    EXPECT_EQ(split.nodes, serial.nodes) << threads;
    EXPECT_EQ(split.normals, serial.normals) << threads;
    EXPECT_EQ(split.adjacency, serial.adjacency) << threads;
  }
}

// The unorganized budget coarsens a densely sampled surface to about voxel_target_nodes nodes
// and leaves a sparse cloud at the scene-wide voxel (what an unlimited voxel_target_nodes gives).
TEST(SegmentVoxelGraph, OnlyADenseSurfaceIsGriddedCoarser) {
  config::SegmentConfig cfg;
  config::SegmentConfig unlimited = cfg;
  unlimited.voxel_target_nodes = std::int64_t{1} << 40;
  const PointList dense = tilted_box(100000, 5);
  const double scene = budget_voxel(dense, unlimited);
  ASSERT_GT(scene, 0.0);
  ASSERT_GT(static_cast<double>(geometry::count_occupied_voxels(dense, scene)),
            1.3 * static_cast<double>(cfg.voxel_target_nodes));  // the case the budget is for
  EXPECT_GT(budget_voxel(dense, cfg), 1.1 * scene);
  // A surface fills cells with the inverse square of the edge: about the budget, within 30%.
  const double nodes = static_cast<double>(build_voxel_graph(dense, cfg).size());
  EXPECT_NEAR(nodes, static_cast<double>(cfg.voxel_target_nodes), 0.3 * static_cast<double>(cfg.voxel_target_nodes));
  const PointList sparse = tilted_box(5000, 6);
  EXPECT_EQ(budget_voxel(sparse, cfg), budget_voxel(sparse, unlimited));
}

}  // namespace
}  // namespace cloudshape::segment
