// k-NN and radius queries against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/kdtree.hpp"

namespace cloudshape::geometry {
namespace {

// `count` points uniform in the cube [-1, 1]^3, drawn from `rng` (later queries draw on from it).
PointList cube_points(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> u(-1, 1);
  PointList pts;
  for (int i = 0; i < count; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
  return pts;
}

TEST(KdTree, AnOwningTreeAnswersAsOneOverTheListItWasMadeFrom) {
  std::mt19937_64 rng(4);
  const PointList pts = cube_points(rng, 2000);
  std::uniform_real_distribution<double> u(-1, 1);
  const KdTree over(pts);
  PointList copy = pts;
  const KdTree owning(std::move(copy));
  copy.assign(10, Point::Zero());  // the caller's list is free again: the tree kept its own
  ASSERT_EQ(owning.points().size(), pts.size());
  std::vector<std::uint32_t> a, b;
  std::vector<double> da, db;
  for (int q = 0; q < 50; ++q) {
    const Point query(u(rng), u(rng), u(rng));
    over.knn(query, 14, a, &da);
    owning.knn(query, 14, b, &db);
    EXPECT_EQ(a, b);
    EXPECT_EQ(da, db);
    over.radius(query, 0.2, a);
    owning.radius(query, 0.2, b);
    EXPECT_EQ(a, b);  // the same order too: RANSAC draws from it by position
  }
}

TEST(KdTree, KnnMatchesBruteForce) {
  std::mt19937_64 rng(1);
  const PointList pts = cube_points(rng, 3000);
  std::uniform_real_distribution<double> u(-1, 1);
  const KdTree tree(pts);
  std::vector<std::uint32_t> idx;
  std::vector<double> d2;
  for (int q = 0; q < 50; ++q) {
    const Point query(u(rng), u(rng), u(rng));
    tree.knn(query, 16, idx, &d2);
    std::vector<double> all;
    for (const auto& p : pts) all.push_back((p - query).squaredNorm());
    std::sort(all.begin(), all.end());
    ASSERT_EQ(idx.size(), 16u);
    for (int k = 0; k < 16; ++k) EXPECT_DOUBLE_EQ(d2[k], all[k]);
  }
}

TEST(KdTree, NearestOtherIsKnnsSecondDistance) {
  std::mt19937_64 rng(6);
  PointList pts = cube_points(rng, 3000);
  for (int i = 0; i < 40; ++i) pts.push_back(pts[i * 7]);  // duplicates: 0
  const KdTree tree(pts);
  std::vector<std::uint32_t> idx;
  std::vector<double> d2;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    tree.knn(pts[i], 2, idx, &d2);
    ASSERT_EQ(tree.nearest_other_sq_dist(i), d2[1]) << i;
  }
  EXPECT_EQ(tree.nearest_other_sq_dist(7), 0.0);
}

TEST(KdTree, RadiusFindsExactlyThePointsInside) {
  PointList pts;
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 10; ++y) pts.emplace_back(x, y, 0);
  const KdTree tree(pts);
  std::vector<std::uint32_t> idx;
  tree.radius(Point(5, 5, 0), 1.01, idx);
  EXPECT_EQ(idx.size(), 5u);  // the point and its four axis neighbours
}

// any_within is radius() not empty, also at the radius' edge: a query exactly a point's
// distance away is not within (strictly less, as radius() counts).
TEST(KdTree, AnyWithinIsWhetherRadiusFindsAny) {
  std::mt19937_64 rng(11);
  const PointList pts = cube_points(rng, 3000);
  const KdTree tree(pts);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::vector<std::uint32_t> found;
  std::size_t hits = 0;
  for (int q = 0; q < 400; ++q) {
    const Point query(u(rng), u(rng), u(rng));
    const double r = 0.01 + 0.001 * q;
    tree.radius(query, r, found);
    EXPECT_EQ(tree.any_within(query, r), !found.empty()) << "query " << q;
    hits += found.empty() ? 0 : 1;
  }
  EXPECT_GT(hits, 50u);
  EXPECT_LT(hits, 350u);
  const KdTree one(PointList{Point(1.0, 0.0, 0.0)});
  EXPECT_FALSE(one.any_within(Point::Zero(), 1.0));
  EXPECT_TRUE(one.any_within(Point::Zero(), std::nextafter(1.0, 2.0)));
}

TEST(KdTree, KIsClampedToTheCloud) {
  const PointList pts{Point(0, 0, 0), Point(1, 0, 0)};
  const KdTree tree(pts);
  std::vector<std::uint32_t> idx;
  tree.knn(Point(0, 0, 0), 10, idx);
  EXPECT_EQ(idx.size(), 2u);
}

}  // namespace
}  // namespace cloudshape::geometry
