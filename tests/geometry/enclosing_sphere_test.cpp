// Minimal enclosing sphere against analytic answers and a brute-force search.
#include <gtest/gtest.h>

#include <random>

#include "geometry/enclosing_sphere.hpp"

namespace cloudshape::geometry {
namespace {

bool encloses(const Sphere& s, const PointList& pts, double tol) {
  for (const auto& p : pts)
    if ((p - s.center).norm() > s.radius + tol) return false;
  return true;
}

// Smallest sphere among those spanned by 2, 3 or 4 of the points that hold them all:
// the minimal enclosing sphere is always one of them.
double brute_force_radius(const PointList& pts) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = pts.size();
  auto consider = [&](const PointList& support) {
    const Sphere s = minimal_enclosing_sphere(support);
    if (s.radius < best && encloses(s, pts, 1e-9)) best = s.radius;
  };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      consider({pts[a], pts[b]});
      for (std::size_t c = b + 1; c < n; ++c) {
        consider({pts[a], pts[b], pts[c]});
        for (std::size_t d = c + 1; d < n; ++d) consider({pts[a], pts[b], pts[c], pts[d]});
      }
    }
  return best;
}

TEST(MinimalEnclosingSphere, SinglePointHasZeroRadius) {
  const Sphere s = minimal_enclosing_sphere({Point(1, 2, 3)});
  EXPECT_DOUBLE_EQ(s.radius, 0.0);
  EXPECT_TRUE(s.center.isApprox(Point(1, 2, 3)));
}

TEST(MinimalEnclosingSphere, TwoPointsSpanADiameter) {
  const Sphere s = minimal_enclosing_sphere({Point(0, 0, 0), Point(2, 0, 0)});
  EXPECT_NEAR(s.radius, 1.0, 1e-12);
  EXPECT_NEAR((s.center - Point(1, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(MinimalEnclosingSphere, CubeCornersGiveTheCircumsphere) {
  PointList pts;
  for (int x : {-1, 1})
    for (int y : {-1, 1})
      for (int z : {-1, 1}) pts.emplace_back(x + 5.0, y - 2.0, z + 0.5);
  pts.emplace_back(5.0, -2.0, 0.5);  // an interior point changes nothing
  const Sphere s = minimal_enclosing_sphere(pts);
  EXPECT_NEAR(s.radius, std::sqrt(3.0), 1e-9);
  EXPECT_NEAR((s.center - Point(5, -2, 0.5)).norm(), 0.0, 1e-9);
}

TEST(MinimalEnclosingSphere, ObtuseTriangleUsesItsLongestSide) {
  // The circumcircle of an obtuse triangle is larger than needed: the longest side is the diameter.
  const Sphere s = minimal_enclosing_sphere({Point(0, 0, 0), Point(4, 0, 0), Point(2, 0.5, 0)});
  EXPECT_NEAR(s.radius, 2.0, 1e-12);
}

TEST(MinimalEnclosingSphere, PointsOnASphereGiveThatSphere) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  PointList pts;
  for (int i = 0; i < 2000; ++i) pts.push_back(Point(1, 1, 1) + 3.0 * Point(g(rng), g(rng), g(rng)).normalized());
  const Sphere s = minimal_enclosing_sphere(pts);
  EXPECT_NEAR(s.radius, 3.0, 1e-2);
  EXPECT_LT((s.center - Point(1, 1, 1)).norm(), 2e-2);
  EXPECT_TRUE(encloses(s, pts, 1e-9));
}

TEST(MinimalEnclosingSphere, MatchesBruteForceOnRandomSets) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    PointList pts;
    for (int i = 0; i < 10; ++i) pts.emplace_back(u(rng), 0.5 * u(rng), 2.0 * u(rng));
    const Sphere s = minimal_enclosing_sphere(pts);
    EXPECT_TRUE(encloses(s, pts, 1e-9)) << "trial " << trial;
    EXPECT_NEAR(s.radius, brute_force_radius(pts), 1e-9) << "trial " << trial;
  }
}

TEST(MinimalEnclosingSphere, CoplanarAndCollinearSetsAreHandled) {
  PointList line, square;
  for (int i = 0; i <= 10; ++i) line.emplace_back(i, 2.0 * i, 0.0);
  EXPECT_NEAR(minimal_enclosing_sphere(line).radius, 0.5 * std::sqrt(500.0), 1e-9);
  for (int x = 0; x <= 4; ++x)
    for (int y = 0; y <= 4; ++y) square.emplace_back(x, y, 1.0);
  EXPECT_NEAR(minimal_enclosing_sphere(square).radius, 2.0 * std::sqrt(2.0), 1e-9);
}

}  // namespace
}  // namespace cloudshape::geometry
