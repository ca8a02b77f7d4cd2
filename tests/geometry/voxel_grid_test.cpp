// Voxel grid centroids, its isolated-voxel filter, and the resolution estimate.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/kdtree.hpp"
#include "geometry/voxel_grid.hpp"

namespace cloudshape::geometry {
namespace {

PointList grid(int n, double step) {
  PointList pts;
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y) pts.emplace_back(x * step, y * step, 0.0);
  return pts;
}

TEST(VoxelGrid, ReplacesEachVoxelByItsCentroid) {
  // 4 points in one voxel, 1 in another.
  const PointList pts{Point(0.1, 0.1, 0.1), Point(0.3, 0.1, 0.1), Point(0.1, 0.3, 0.1),
                      Point(0.3, 0.3, 0.1), Point(1.5, 0.1, 0.1)};
  const PointList out = voxel_grid_downsample(pts, 1.0);
  ASSERT_EQ(out.size(), 2u);
  const bool first_is_cluster = out[0].x() < 1.0;
  EXPECT_LT((out[first_is_cluster ? 0 : 1] - Point(0.2, 0.2, 0.1)).norm(), 1e-12);
}

TEST(VoxelGrid, NonPositiveSizeKeepsTheCloud) {
  const PointList pts = grid(5, 1.0);
  EXPECT_EQ(voxel_grid_downsample(pts, 0.0).size(), pts.size());
}

TEST(VoxelGrid, DenormalVoxelOrOverflowingExtentKeepsTheCloud) {
  // Found by fuzzing ingest: 1 / denormal = inf, and 0 * inf = NaN was cast to an integer.
  const PointList tiny{Point(0, 0, 0), Point(4e-321, 0, 0), Point(0, 4e-321, 0)};
  EXPECT_EQ(voxel_grid_downsample(tiny, 2e-323), tiny);
  const PointList huge{Point(-1e308, 0, 0), Point(1e308, 1, 1), Point(0, 0, 0)};
  EXPECT_EQ(voxel_grid_downsample(huge, 1.0), huge);
}

TEST(VoxelGrid, IsolatedVoxelsAreDroppedOnlyWhenRare) {
  PointList pts = grid(40, 0.1);  // dense sheet: every voxel has neighbours
  pts.emplace_back(10.0, 10.0, 10.0);  // a stray point far away
  std::size_t isolated = 0;
  const PointList out = voxel_grid_downsample(pts, 0.1, 2, &isolated);
  EXPECT_EQ(isolated, 1u);
  EXPECT_EQ(out.size(), 1600u);
  // Sampling sparser than the grid: everything would look isolated, so nothing is dropped.
  const PointList sparse = grid(10, 1.0);
  EXPECT_EQ(voxel_grid_downsample(sparse, 0.1, 2, &isolated).size(), sparse.size());
  EXPECT_EQ(isolated, 0u);
}

// The count the voxel-size search uses is the downsampled cloud's size, degenerate grids included.
TEST(VoxelGrid, CountOfOccupiedVoxelsIsTheDownsampledSize) {
  PointList pts = grid(40, 0.37);
  for (Point& p : pts) p.z() = 0.05 * std::sin(p.x() * 3.0 + p.y());
  for (double voxel : {0.1, 0.37, 0.5, 1.3, 7.0, 0.0, -1.0, 1e-310}) {
    EXPECT_EQ(count_occupied_voxels(pts, voxel), voxel_grid_downsample(pts, voxel).size()) << "voxel " << voxel;
  }
  EXPECT_EQ(count_occupied_voxels({}, 1.0), 0u);
}

TEST(Resolution, MeanNearestNeighbourOfARegularGrid) {
  EXPECT_NEAR(mean_nearest_neighbour_distance(grid(30, 0.25)), 0.25, 1e-12);
  EXPECT_EQ(mean_nearest_neighbour_distance(PointList{Point(0, 0, 0)}), 0.0);
}

TEST(Resolution, ATreeOverThePointsGivesTheListsValueExactly) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t n : {2u, 500u, 9000u, 60000u}) {
    PointList pts;
    for (std::size_t i = 0; i < n; ++i) pts.emplace_back(u(rng), u(rng), 0.1 * u(rng));
    const KdTree tree(pts);
    EXPECT_EQ(mean_nearest_neighbour_distance(tree), mean_nearest_neighbour_distance(pts)) << n;
    EXPECT_EQ(mean_nearest_neighbour_distance(tree, 100), mean_nearest_neighbour_distance(pts, 100)) << n;
  }
}

}  // namespace
}  // namespace cloudshape::geometry
