// Minimal enclosing sphere against analytic answers and an independent brute-force search.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "geometry/enclosing_sphere.hpp"

namespace cloudshape::geometry {
namespace {

bool encloses(const Sphere& s, const PointList& pts, double tol) {
  for (const auto& p : pts)
    if ((p - s.center).norm() > s.radius + tol) return false;
  return true;
}

// The oracle, independent of the code under test: the minimal enclosing sphere is fixed by
// 2, 3 or 4 points on its surface (the diametral sphere of a pair, the circumcircle of a
// triangle in its own plane, the circumsphere of a tetrahedron), so the smallest of those
// spheres that holds every point is it. Degenerate triples and quadruples are skipped:
// their points are held by a sphere of another kind.
struct Ball {
  Point center;
  double radius;
};

std::optional<Ball> circumcircle(const Point& a, const Point& b, const Point& c) {
  const Eigen::Vector3d u = b - a, v = c - a, n = u.cross(v);
  if (n.squaredNorm() < 1e-18) return std::nullopt;
  const Eigen::Vector3d to_center =
      (u.squaredNorm() * v.cross(n) + v.squaredNorm() * n.cross(u)) / (2.0 * n.squaredNorm());
  return Ball{a + to_center, to_center.norm()};
}

std::optional<Ball> circumsphere(const Point& a, const Point& b, const Point& c, const Point& d) {
  Eigen::Matrix3d m;
  m << (b - a).transpose(), (c - a).transpose(), (d - a).transpose();
  if (std::abs(m.determinant()) < 1e-12) return std::nullopt;
  const Eigen::Vector3d rhs(0.5 * (b - a).squaredNorm(), 0.5 * (c - a).squaredNorm(),
                            0.5 * (d - a).squaredNorm());
  const Eigen::Vector3d to_center = m.fullPivLu().solve(rhs);
  return Ball{a + to_center, to_center.norm()};
}

Ball brute_force(const PointList& pts) {
  Ball best{Point::Zero(), std::numeric_limits<double>::infinity()};
  auto consider = [&](const std::optional<Ball>& b) {
    if (!b || b->radius >= best.radius) return;
    for (const auto& p : pts)
      if ((p - b->center).norm() > b->radius + 1e-9) return;
    best = *b;
  };
  const std::size_t n = pts.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      consider(Ball{0.5 * (pts[a] + pts[b]), 0.5 * (pts[a] - pts[b]).norm()});
      for (std::size_t c = b + 1; c < n; ++c) {
        consider(circumcircle(pts[a], pts[b], pts[c]));
        for (std::size_t d = c + 1; d < n; ++d)
          consider(circumsphere(pts[a], pts[b], pts[c], pts[d]));
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
    const Ball oracle = brute_force(pts);
    EXPECT_NEAR(s.radius, oracle.radius, 1e-9) << "trial " << trial;
    EXPECT_LT((s.center - oracle.center).norm(), 1e-6) << "trial " << trial;
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

// A cone's base rim: thousands of points within a hair of one sphere, each a restart of the
// incremental loops; the sphere is the rim's (the apex lies inside it), found as exactly.
TEST(MinimalEnclosingSphere, AConesRimOfNearlyCosphericalPoints) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * 3.14159265358979323846),
      jitter(-1e-7, 1e-7);
  PointList pts{Point(0, 0, 4)};
  for (int i = 0; i < 5000; ++i) {
    const double t = angle(rng), r = 10.0 * (1.0 + jitter(rng));
    pts.emplace_back(r * std::cos(t), r * std::sin(t), jitter(rng));
  }
  const Sphere s = minimal_enclosing_sphere(pts);
  EXPECT_NEAR(s.radius, 10.0, 1e-5);
  EXPECT_LT(s.center.norm(), 1e-5);
  EXPECT_TRUE(encloses(s, pts, 1e-9));
}

// Far from the origin and at any scale, the same sphere (shifted, scaled).
TEST(MinimalEnclosingSphere, FarAndHugeCoordinates) {
  const PointList unit{Point(0, 0, 0), Point(2, 0, 0), Point(1, 0.5, 0), Point(1, 0, 0.5)};
  for (const double scale : {1e-3, 1.0, 1e6, 1e100}) {
    PointList pts;
    for (const Point& p : unit) pts.push_back(Point(1e3, -2e3, 5e2) + scale * p);
    const Sphere s = minimal_enclosing_sphere(pts);
    EXPECT_NEAR(s.radius / scale, 1.0, 1e-9) << "scale " << scale;
    EXPECT_LT((s.center - (Point(1e3, -2e3, 5e2) + scale * Point(1, 0, 0))).norm() / scale, 1e-9)
        << "scale " << scale;
  }
}

// Points a hair inside, on and outside the loops' threshold, in many directions, far from the
// origin and near it: the scan settles by squared distance only what the exact test would settle
// the same way, and hands it the rest (a band narrower than the squares' rounding fails here).
TEST(MinimalEnclosingSphere, TheScanAnswersAsTheExactTestAtTheThreshold) {
  std::mt19937_64 rng(21);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int trial = 0; trial < 200; ++trial) {
    const Sphere s{Point(u(rng), u(rng), u(rng)),
                   std::abs(u(rng)) * (trial % 2 ? 1e-6 : 1.0) + 1e-9};
    const double threshold = s.radius * (1.0 + 1e-10) + 1e-12;
    PointList pts;
    for (int k = 0; k < 64; ++k) {
      const Eigen::Vector3d direction = Point(g(rng), g(rng), g(rng)).normalized();
      for (const double r :
           {std::nextafter(threshold, 0.0), threshold, std::nextafter(threshold, 1e300)})
        pts.push_back(s.center + r * direction);
    }
    std::vector<std::size_t> got, want;
    for (std::size_t i = detail::first_outside(s, pts, 0, pts.size()); i < pts.size();
         i = detail::first_outside(s, pts, i + 1, pts.size()))
      got.push_back(i);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (detail::outside(s, pts[i])) want.push_back(i);
    }
    ASSERT_EQ(got, want) << "trial " << trial;
    ASSERT_FALSE(want.empty());
  }
}

}  // namespace
}  // namespace cloudshape::geometry
