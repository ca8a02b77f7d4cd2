// Voxel grid centroids, its isolated-voxel filter, and the resolution estimate.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include "geometry/kdtree.hpp"
#include "geometry/voxel_grid.hpp"
#include "parallel/thread_pool.hpp"

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

// The size a grid would have, counted from the voxels' bits (isolated ones left out as the grid
// leaves them out, or all kept where they are many), with and without a pool, and from the grid
// itself where the bits would be too many or a point lies outside the bounds given.
TEST(VoxelGrid, DownsampledSizeIsTheGridsSize) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PointList pts;
  for (int i = 0; i < 300000; ++i)
    pts.emplace_back(u(rng), 0.5 * u(rng), 0.02 * u(rng) + 0.1 * std::sin(3.0 * i));
  for (int i = 0; i < 40; ++i)
    pts.emplace_back(3.0 + 0.5 * i, 2.0, 1.0);  // isolated voxels at most voxels
  parallel::ThreadPool two(2);
  for (double voxel : {0.02, 0.05, 0.2, 0.9, 0.0, -1.0}) {
    for (int neighbours : {0, 2, 5}) {
      const std::size_t grid = voxel_grid_downsample(pts, voxel, neighbours).size();
      EXPECT_EQ(downsampled_size(pts, voxel, neighbours), grid)
          << "voxel " << voxel << ", " << neighbours;
      EXPECT_EQ(downsampled_size(pts, voxel, neighbours, nullptr, &two), grid)
          << "voxel " << voxel << ", " << neighbours;
    }
  }
  // The filter's own rule: a cloud of mostly isolated voxels keeps them all.
  const PointList sparse = grid(20, 1.0);
  EXPECT_EQ(downsampled_size(sparse, 0.3, 2), voxel_grid_downsample(sparse, 0.3, 2).size());
  EXPECT_EQ(downsampled_size(sparse, 0.3, 2), sparse.size());
  // No count where only the grid tells: more voxels than bits a point, or points outside the
  // bounds given.
  EXPECT_EQ(downsampled_size(pts, 0.0005, 2), std::nullopt);
  Bounds wrong;
  wrong.min = Point(-1.0, -0.5, -0.1);
  wrong.max = Point(0.0, 0.0, 0.0);
  EXPECT_EQ(downsampled_size(pts, 0.05, 2, &wrong, &two), std::nullopt);
  EXPECT_EQ(downsampled_size({}, 1.0, 2), 0u);
}

// The centroids in the order of each voxel's first point, summed in point order: what both the
// dense array (a compact cloud) and the hash map (a sparse one) must give to the bit.
PointList reference_centroids(const PointList& pts, double voxel) {
  const Bounds b = bounding_box(pts);
  std::map<std::array<std::int64_t, 3>, std::size_t> slot;
  std::vector<std::pair<Point, int>> acc;
  for (const Point& p : pts) {
    const Eigen::Vector3d q = (p - b.min) * (1.0 / voxel);
    const std::array<std::int64_t, 3> key{static_cast<std::int64_t>(q.x()), static_cast<std::int64_t>(q.y()),
                                          static_cast<std::int64_t>(q.z())};
    const auto [it, inserted] = slot.emplace(key, acc.size());
    if (inserted) acc.emplace_back(Point::Zero(), 0);
    acc[it->second].first += p;
    ++acc[it->second].second;
  }
  PointList out;
  for (const auto& [sum, count] : acc) out.push_back(sum / static_cast<double>(count));
  return out;
}

TEST(VoxelGrid, CompactAndSparseCloudsGiveTheCentroidsInFirstPointOrder) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointList compact;  // many points a voxel: the grid fits an array
  for (int i = 0; i < 20000; ++i) compact.emplace_back(u(rng), 0.5 * u(rng), 0.2 * u(rng));
  PointList sparse = compact;  // one point far off: the grid does not
  sparse.resize(300);
  sparse.emplace_back(500.0, -300.0, 40.0);
  for (const PointList* pts : {&compact, &sparse}) {
    for (double voxel : {0.05, 0.13, 0.4}) {
      EXPECT_EQ(voxel_grid_downsample(*pts, voxel), reference_centroids(*pts, voxel)) << pts->size() << " " << voxel;
      EXPECT_EQ(count_occupied_voxels(*pts, voxel), reference_centroids(*pts, voxel).size());
    }
  }
}

TEST(VoxelGrid, AnIsolatedVoxelInsideACompactCloudIsDropped) {
  PointList pts;
  for (int x = 0; x < 40; ++x)
    for (int y = 0; y < 40; ++y)
      for (int k = 0; k < 8; ++k) pts.emplace_back(x * 0.1 + 0.01 * k, y * 0.1 + 0.005 * k, 0.0);
  pts.emplace_back(2.05, 2.05, 0.55);  // within the sheet's box, five voxels above it
  std::size_t isolated = 0;
  const PointList out = voxel_grid_downsample(pts, 0.1, 2, &isolated);
  EXPECT_EQ(isolated, 1u);
  EXPECT_EQ(out.size(), 1600u);
}

// The voxel-size search's subsample, strided in place: the copied subsample's box and counts.
TEST(VoxelGrid, AStridedCountIsTheCopiedSubsamplesCount) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  PointList pts;
  for (int i = 0; i < 5000; ++i) pts.emplace_back(n(rng), 2.0 * n(rng), -0.0 * n(rng));
  pts.emplace_back(900.0, 0.0, 0.0);
  for (std::size_t stride : {1u, 2u, 3u, 7u, 5001u, 9000u}) {
    PointList copy;
    for (std::size_t i = 0; i < pts.size(); i += stride) copy.push_back(pts[i]);
    const Bounds b = bounding_box(pts, stride), expected = bounding_box(copy);
    EXPECT_EQ(b.min, expected.min);
    EXPECT_EQ(b.max, expected.max);
    for (double voxel : {0.02, 0.3, 5.0, 0.0}) {
      EXPECT_EQ(count_occupied_voxels(pts, voxel, &b, stride), count_occupied_voxels(copy, voxel)) << stride;
      EXPECT_EQ(count_occupied_voxels(pts, voxel, nullptr, stride), voxel_grid_downsample(copy, voxel).size());
    }
  }
}

// Bounds that are not the points' own box (the header asks for it) put points outside the dense
// array: the count and the grid fall back to the map, and give its voxels, counted by hand here.
TEST(VoxelGrid, PointsOutsideTheBoundsGivenFallBackToTheMap) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointList pts;
  for (int i = 0; i < 4000; ++i) pts.emplace_back(u(rng), u(rng), 0.25 * u(rng));
  const double voxel = 0.05;
  Bounds wrong;  // a small box below the points: every point lies beyond its far corner
  wrong.min = Point(-2.0, -2.0, -2.0);
  wrong.max = Point(-1.9, -1.9, -1.9);
  std::set<std::array<std::int64_t, 3>> cells;
  for (const Point& p : pts) {
    const Eigen::Vector3d q = (p - wrong.min) / voxel;
    cells.insert({static_cast<std::int64_t>(std::floor(q.x())), static_cast<std::int64_t>(std::floor(q.y())),
                  static_cast<std::int64_t>(std::floor(q.z()))});
  }
  EXPECT_EQ(count_occupied_voxels(pts, voxel, &wrong), cells.size());
  EXPECT_EQ(voxel_grid_downsample(pts, voxel, 0, nullptr, &wrong).size(), cells.size());
  // With the points' own box, the same cloud takes the dense paths.
  EXPECT_GT(count_occupied_voxels(pts, voxel), 100u);
}

// Eigen's cwiseMin and cwiseMax, the box bounding_box gave before it compared coordinates itself.
TEST(VoxelGrid, TheBoundingBoxIsEigensToTheBit) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PointList pts{Point(0.0, -0.0, 0.0), Point(-0.0, 0.0, -0.0)};
  for (int i = 0; i < 1000; ++i) pts.emplace_back(u(rng), u(rng), i % 3 == 0 ? 0.0 : -0.0);
  Point lo = pts.front(), hi = pts.front();
  for (const Point& p : pts) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Bounds b = bounding_box(pts);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(std::signbit(b.min[a]), std::signbit(lo[a]));
    EXPECT_EQ(std::signbit(b.max[a]), std::signbit(hi[a]));
  }
  EXPECT_EQ(b.min, lo);
  EXPECT_EQ(b.max, hi);
}

// A pool folds blocks of a large cloud's bounds side by side and counts its parts' voxels in
// arrays of their own: the serial box to the bit (signed zeros in ties too) and the same count,
// strided or not, for the hash map's fall-back too.
TEST(VoxelGrid, APoolGivesTheSameBoxAndCount) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PointList pts;
  for (int i = 0; i < 700000; ++i) {
    pts.emplace_back(u(rng), 0.5 * u(rng), i % 5 == 0 ? (i % 2 ? 0.0 : -0.0) : 0.1 * u(rng));
  }
  pts[400000] = Point(-1.5, -0.0, 0.0);
  pts[650000] = Point(-1.5, 0.0, -0.0);
  for (std::size_t threads : {2u, 3u}) {
    parallel::ThreadPool pool(threads);
    for (std::size_t stride : {1u, 3u}) {
      const Bounds serial = bounding_box(pts, stride), split = bounding_box(pts, stride, &pool);
      for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(std::signbit(split.min[a]), std::signbit(serial.min[a])) << threads << " " << stride;
        EXPECT_EQ(std::signbit(split.max[a]), std::signbit(serial.max[a])) << threads << " " << stride;
      }
      EXPECT_EQ(split.min, serial.min);
      EXPECT_EQ(split.max, serial.max);
      for (double voxel : {0.01, 0.2}) {
        EXPECT_EQ(count_occupied_voxels(pts, voxel, nullptr, stride, &pool), count_occupied_voxels(pts, voxel, nullptr, stride))
            << threads << " threads, stride " << stride << ", voxel " << voxel;
      }
    }
    Bounds wrong;
    wrong.min = Point(-3.0, -3.0, -3.0);
    wrong.max = Point(-2.9, -2.9, -2.9);
    EXPECT_EQ(count_occupied_voxels(pts, 0.05, &wrong, 1, &pool), count_occupied_voxels(pts, 0.05, &wrong));
  }
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

// The tree's searches in blocks on a pool, summed in sample order: the serial value, to the bit.
TEST(Resolution, APoolGivesTheSameValue) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t n : {500u, 9000u, 60000u}) {
    PointList pts;
    for (std::size_t i = 0; i < n; ++i) pts.emplace_back(u(rng), u(rng), 0.1 * u(rng));
    const KdTree tree(pts);
    const double serial = mean_nearest_neighbour_distance(tree);
    for (std::size_t threads : {2u, 3u}) {
      parallel::ThreadPool pool(threads);
      EXPECT_EQ(mean_nearest_neighbour_distance(tree, 4000, &pool), serial) << n << " points, " << threads;
      EXPECT_EQ(mean_nearest_neighbour_distance(pts, 4000, &pool), serial) << n << " points, " << threads;
    }
  }
}

}  // namespace
}  // namespace cloudshape::geometry
