// The grid's nearest-neighbour answers against brute force: exactly the same distances and
// neighbours, on a surface, a volume, a line with an outlier, and a degenerate cloud.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/grid_neighbours.hpp"
#include "geometry/kdtree.hpp"

namespace cloudshape::geometry {
namespace {

double sq(const Point& a, const Point& b) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i) d += (a[i] - b[i]) * (a[i] - b[i]);
  return d;
}

// Each point's k nearest by brute force, nearest first, ties by index.
std::vector<std::uint32_t> brute_knn(const PointList& pts, std::size_t i, std::size_t k) {
  std::vector<std::pair<double, std::uint32_t>> all;
  for (std::size_t j = 0; j < pts.size(); ++j) all.emplace_back(sq(pts[i], pts[j]), static_cast<std::uint32_t>(j));
  std::sort(all.begin(), all.end());
  std::vector<std::uint32_t> out;
  for (std::size_t j = 0; j < k; ++j) out.push_back(all[j].second);
  return out;
}

PointList sphere_surface(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  PointList pts;
  for (std::size_t i = 0; i < n; ++i) pts.push_back(Point(g(rng), g(rng), g(rng)).normalized() * 5.0);
  return pts;
}

PointList volume(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  PointList pts;
  for (std::size_t i = 0; i < n; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
  return pts;
}

PointList line_with_outlier() {
  PointList pts;
  for (int i = 0; i < 300; ++i) pts.emplace_back(0.01 * i, 0.0, 0.0);
  pts.emplace_back(100.0, 50.0, -20.0);
  return pts;
}

void expect_nearest_other_exact(const PointList& pts) {
  std::vector<std::uint32_t> queries;
  for (std::uint32_t i = 0; i < pts.size(); i += 7) queries.push_back(i);
  const std::vector<double> got = nearest_other_distances(pts, queries);
  ASSERT_EQ(got.size(), queries.size());
  for (std::size_t q = 0; q < queries.size(); ++q) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < pts.size(); ++j) {
      if (j != queries[q]) best = std::min(best, sq(pts[queries[q]], pts[j]));
    }
    EXPECT_EQ(got[q], std::sqrt(best)) << "query " << queries[q];  // bit-exact: the same sum
  }
}

void expect_knn_exact(const PointList& pts, std::size_t k, double cell) {
  std::vector<std::uint32_t> got;
  all_nearest_neighbours(pts, k, cell, got);
  ASSERT_EQ(got.size(), pts.size() * k);
  for (std::size_t i = 0; i < pts.size(); i += 5) {
    const std::vector<std::uint32_t> want = brute_knn(pts, i, k);
    for (std::size_t j = 0; j < k; ++j) ASSERT_EQ(got[i * k + j], want[j]) << "point " << i << " rank " << j;
  }
}

TEST(GridNeighbours, NearestOtherIsExactOnSurfaceVolumeAndLine) {
  expect_nearest_other_exact(sphere_surface(4000, 1));
  expect_nearest_other_exact(volume(3000, 2));
  expect_nearest_other_exact(line_with_outlier());
}

// A cube of 250 000 points has more cells of its grid than four a point: the hash map's path
// (smaller clouds take the dense array's). The kd-tree's distances are the same sums.
TEST(GridNeighbours, NearestOtherIsExactWhereTheCellsOutnumberThePoints) {
  const PointList pts = volume(250000, 7);
  std::vector<std::uint32_t> queries;
  for (std::uint32_t i = 0; i < pts.size(); i += 499) queries.push_back(i);
  const std::vector<double> got = nearest_other_distances(pts, queries);
  const KdTree tree(pts);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    EXPECT_EQ(got[q], std::sqrt(tree.nearest_other_sq_dist(queries[q]))) << "query " << queries[q];
  }
}

// Bounds that are not the points' own (smaller: some of the queries' blocks reach beyond them)
// take the hash map of block cells instead of the bits over the bounds: the same distances.
TEST(GridNeighbours, NearestOtherIsExactWithBoundsSmallerThanThePoints) {
  const PointList pts = volume(250000, 8);
  std::vector<std::uint32_t> queries;
  for (std::uint32_t i = 0; i < pts.size(); i += 499) queries.push_back(i);
  Bounds smaller = bounding_box(pts);
  smaller.max = smaller.min + 0.8 * (smaller.max - smaller.min);
  parallel::ThreadPool two(2);
  const KdTree tree(pts);
  for (parallel::ThreadPool* pool : {static_cast<parallel::ThreadPool*>(nullptr), &two}) {
    const std::vector<double> got = nearest_other_distances(pts, queries, pool, &smaller);
    for (std::size_t q = 0; q < queries.size(); ++q) {
      EXPECT_EQ(got[q], std::sqrt(tree.nearest_other_sq_dist(queries[q])))
          << "query " << queries[q];
    }
  }
}

// Points off a surface by two to three of the grid's cells have no neighbour in their own block
// of cells: a search in wider cells answers them together, the farthest a scan. Every answer as
// brute force's.
void expect_far_points_exact(std::size_t surface_points) {
  PointList pts = sphere_surface(surface_points, 11);
  std::mt19937_64 rng(12);
  std::normal_distribution<double> g(0.0, 1.0);
  // Two to three of the grid's cells off the surface, whatever its density.
  const double cells = std::sqrt(4000.0 / static_cast<double>(surface_points));
  std::uniform_real_distribution<double> off(3.0 * cells, 6.0 * cells);
  std::vector<std::uint32_t> queries;
  for (int i = 0; i < 12; ++i) {
    queries.push_back(static_cast<std::uint32_t>(pts.size()));
    pts.push_back(Point(g(rng), g(rng), g(rng)).normalized() * (5.0 + off(rng)));
  }
  for (const double far : {13.0, -14.0}) {
    queries.push_back(static_cast<std::uint32_t>(pts.size()));
    pts.emplace_back(far, 0.5 * far, 0.0);
  }
  for (std::uint32_t i = 0; i < surface_points; i += 97) queries.push_back(i);
  parallel::ThreadPool two(2);
  for (parallel::ThreadPool* pool : {static_cast<parallel::ThreadPool*>(nullptr), &two}) {
    const std::vector<double> got = nearest_other_distances(pts, queries, pool);
    ASSERT_EQ(got.size(), queries.size());
    for (std::size_t q = 0; q < queries.size(); ++q) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < pts.size(); ++j) {
        if (j != queries[q]) best = std::min(best, sq(pts[queries[q]], pts[j]));
      }
      EXPECT_EQ(got[q], std::sqrt(best)) << surface_points << " points, query " << queries[q];
    }
  }
}

TEST(GridNeighbours, NearestOtherIsExactForPointsFarFromTheirBlock) {
  expect_far_points_exact(4000);
  expect_far_points_exact(40000);  // several blocks of points on the pool, their minima joined
}

TEST(GridNeighbours, DuplicatesAndIdenticalPointsGiveZero) {
  PointList pts = sphere_surface(500, 3);
  pts.push_back(pts[10]);
  const std::vector<double> d = nearest_other_distances(pts, {10, 500});
  EXPECT_EQ(d[0], 0.0);
  EXPECT_EQ(d[1], 0.0);
  const PointList same(20, Point(1.0, 2.0, 3.0));
  EXPECT_EQ(nearest_other_distances(same, {0, 19}), std::vector<double>({0.0, 0.0}));
}

TEST(GridNeighbours, KnnIsExactForAnyCellSize) {
  const PointList surface = sphere_surface(3000, 4);
  // Cells about the 16th neighbour's distance, far smaller (kd-tree fall-backs) and larger.
  expect_knn_exact(surface, 16, 0.6);
  expect_knn_exact(surface, 16, 0.05);
  expect_knn_exact(surface, 16, 3.0);
  // The 16th beyond the first block's reach but within two rings of cells, or beyond.
  expect_knn_exact(surface, 16, 0.3);
  expect_knn_exact(surface, 16, 0.2);
  expect_knn_exact(volume(2000, 5), 8, 0.5);
  expect_knn_exact(line_with_outlier(), 16, 0.03);
}

// A lattice: every distance tied many times over, the ties going by index in the wider rings too.
TEST(GridNeighbours, KnnTiesGoByIndexInWiderRings) {
  PointList lattice;
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 12; ++y) lattice.emplace_back(0.1 * x, 0.1 * y, 0.0);
  expect_knn_exact(lattice, 20, 0.07);
  expect_knn_exact(lattice, 9, 0.05);
}

// With a pool, blocks of cells and the kd-tree fall-backs run on its threads: the same rows as
// without one, on clouds whose sparse points take the fall-back (small cells, the outlier).
TEST(GridNeighbours, AnyPoolGivesTheSameRows) {
  const PointList surface = sphere_surface(6000, 3);
  for (const auto& [pts, cell] : std::vector<std::pair<PointList, double>>{
           {surface, 0.6}, {surface, 0.05}, {line_with_outlier(), 0.03}}) {
    std::vector<std::uint32_t> serial;
    all_nearest_neighbours(pts, 16, cell, serial);
    for (std::size_t threads : {1u, 2u, 3u}) {
      parallel::ThreadPool pool(threads);
      std::vector<std::uint32_t> got;
      all_nearest_neighbours(pts, 16, cell, got, &pool);
      EXPECT_EQ(got, serial) << threads << " threads, cell " << cell;
    }
  }
}

// The pass over the points in blocks (several of them at 40 000 points), each block's minima
// joined: bit for bit the serial distances, with any number of threads.
TEST(GridNeighbours, NearestOtherWithAPoolIsTheSame) {
  const PointList pts = sphere_surface(40000, 6);
  std::vector<std::uint32_t> queries;
  for (std::uint32_t i = 0; i < pts.size(); i += 13) queries.push_back(i);
  const std::vector<double> serial = nearest_other_distances(pts, queries);
  for (std::size_t threads : {1u, 2u, 3u}) {
    parallel::ThreadPool pool(threads);
    EXPECT_EQ(nearest_other_distances(pts, queries, &pool), serial) << threads << " threads";
  }
}

TEST(GridNeighbours, FewerPointsThanK) {
  const PointList pts{Point(0, 0, 0), Point(1, 0, 0), Point(0, 2, 0)};
  std::vector<std::uint32_t> got;
  all_nearest_neighbours(pts, 16, 1.0, got);
  EXPECT_EQ(got, std::vector<std::uint32_t>({0, 1, 2, 1, 0, 2, 2, 0, 1}));
  const PointList same(20, Point(1.0, 2.0, 3.0));
  all_nearest_neighbours(same, 4, 0.0, got);  // no grid: every point by the kd-tree, ties by index
  ASSERT_EQ(got.size(), 80u);
  EXPECT_EQ(std::vector<std::uint32_t>(got.begin() + 4, got.begin() + 8), std::vector<std::uint32_t>({0, 1, 2, 3}));
}

}  // namespace
}  // namespace cloudshape::geometry
