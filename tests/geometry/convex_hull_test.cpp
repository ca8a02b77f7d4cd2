// The hull candidates: convex_hull_2d of them is exactly (bit for bit) the hull of all the points,
// on filled, ring, collinear-edged and far-from-origin sets, while most inner points are dropped.
#include "geometry/convex_hull.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace cloudshape::geometry {
namespace {

using Vec2 = Eigen::Vector2d;

// Hull of the candidates against the hull of all: same vertices, same order, same bits.
void expect_same_hull(const std::vector<Vec2>& points) {
  const std::vector<Vec2> all = convex_hull_2d(points);
  const std::vector<Vec2> fewer = convex_hull_2d(hull_candidates(points));
  ASSERT_EQ(fewer.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(fewer[i].x(), all[i].x()) << i;
    EXPECT_EQ(fewer[i].y(), all[i].y()) << i;
  }
}

std::vector<Vec2> rotated(std::vector<Vec2> points, double angle, const Vec2& at) {
  const Eigen::Rotation2Dd r(angle);
  for (Vec2& p : points) p = r * p + at;
  return points;
}

TEST(HullCandidates, FilledSquareKeepsItsHullAndDropsMostPoints) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec2> pts;
  for (int i = 0; i < 4000; ++i) pts.emplace_back(u(rng), u(rng));
  expect_same_hull(pts);
  EXPECT_LT(hull_candidates(pts).size(), pts.size() / 4);
}

TEST(HullCandidates, BoxOutlinesWithCollinearSidesKeepTheirHull) {
  // A box's projected side faces are segments of collinear points up to rounding; the monotone
  // chain keeps or drops each by the sign of a rounded cross product, so every one must reach it.
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::uniform_int_distribution<int> side(0, 4);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Vec2> pts;
    for (int i = 0; i < 2000; ++i) {
      Vec2 p(u(rng) * 3.0, u(rng) * 2.0);
      const int s = side(rng);  // 4: inside (a face across the projection)
      if (s < 4) p[s / 2] = (s % 2 ? 0.5 : -0.5) * (s / 2 ? 2.0 : 3.0);
      pts.push_back(p);
    }
    expect_same_hull(rotated(pts, 0.07 * trial, Vec2(1000.0 * trial, -37.5 * trial)));
  }
}

TEST(HullCandidates, NoisyRingsAndTinyOrDegenerateSetsKeepTheirHull) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  std::vector<Vec2> ring;
  for (int i = 0; i < 3000; ++i) {
    const double a = angle(rng);
    ring.emplace_back(std::cos(a) + noise(rng), std::sin(a) + noise(rng));
  }
  expect_same_hull(rotated(ring, 0.3, Vec2(5e4, 5e4)));
  std::vector<Vec2> line;
  for (int i = 0; i < 100; ++i) line.emplace_back(0.1 * i, 0.2 * i);
  expect_same_hull(line);
  expect_same_hull(std::vector<Vec2>(100, Vec2(1.0, 2.0)));
  expect_same_hull({Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)});
}

}  // namespace
}  // namespace cloudshape::geometry
