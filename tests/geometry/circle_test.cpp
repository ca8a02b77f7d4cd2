// Circumcircle (thesis eq. 3.7-3.8) and least-squares circle and sphere fits.
#include <gtest/gtest.h>

#include <random>

#include "geometry/circle.hpp"

namespace cloudshape::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Circumcircle, RightTriangleHasHalfTheHypotenuse) {
  const auto c = circumcircle(Point(0, 0, 0), Point(3, 0, 0), Point(0, 4, 0));
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->radius, 2.5, 1e-12);
  EXPECT_NEAR((c->center - Point(1.5, 2, 0)).norm(), 0.0, 1e-12);
}

TEST(Circumcircle, EquilateralTriangleInATiltedPlane) {
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 3).normalized();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  const Point centre(4, -1, 2);
  PointList tri;
  for (int k = 0; k < 3; ++k)
    tri.push_back(centre + 7.0 * (std::cos(2 * kPi * k / 3) * u + std::sin(2 * kPi * k / 3) * v));
  const auto c = circumcircle(tri[0], tri[1], tri[2]);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->radius, 7.0, 1e-10);
  EXPECT_NEAR((c->center - centre).norm(), 0.0, 1e-10);
  EXPECT_NEAR(std::abs(c->normal.dot(n)), 1.0, 1e-12);
}

TEST(Circumcircle, CollinearPointsHaveNone) {
  EXPECT_FALSE(circumcircle(Point(0, 0, 0), Point(1, 1, 1), Point(2, 2, 2)));
}

TEST(CircleFit, NoisyArcRecoversCentreAndRadius) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::uniform_real_distribution<double> angle(0.0, kPi / 2);  // a quarter arc biases algebraic fits
  PointList pts;
  std::vector<std::uint32_t> idx;
  for (int i = 0; i < 500; ++i) {
    const double a = angle(rng);
    pts.emplace_back(2 + 5 * std::cos(a) + noise(rng), -1 + 5 * std::sin(a) + noise(rng), 3 + noise(rng));
    idx.push_back(i);
  }
  const auto c = fit_circle_in_plane(pts, idx, Point(0, 0, 3), Eigen::Vector3d::UnitZ());
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->radius, 5.0, 0.01);
  EXPECT_LT((c->center - Point(2, -1, 3)).norm(), 0.02);
}

TEST(SphereFit, CapOfASphere) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  PointList pts;
  for (int i = 0; i < 3000; ++i) {
    Eigen::Vector3d d(g(rng), g(rng), g(rng));
    d.normalize();
    if (d.z() < 0.3) continue;  // a cap, as a single view sees it
    pts.push_back(Point(10, 20, 30) + 0.25 * d);
  }
  const auto s = fit_sphere(pts);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->radius, 0.25, 1e-9);
  EXPECT_LT((s->center - Point(10, 20, 30)).norm(), 1e-9);
  EXPECT_LT(s->rms, 1e-9);
}

TEST(SphereFit, TooFewPointsGiveNothing) {
  EXPECT_FALSE(fit_sphere(PointList{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)}));
}

// The widest gap between angles around the circle: between neighbours, or across the wrap from
// the last back to the first; one angle alone leaves the whole turn.
TEST(WidestAngularGap, BetweenNeighboursOrAcrossTheWrap) {
  const double pi = 3.14159265358979323846;
  std::vector<double> inside = {0.5, -2.0, 1.0, 3.0};  // gaps 2.5, 0.5, 2.0 and across the wrap 1.28
  EXPECT_NEAR(widest_angular_gap(inside), 2.5, 1e-12);
  std::vector<double> wrap = {3.0, -3.0, 0.0};  // gaps 3.0, 3.0 and across the wrap 2 pi - 6
  EXPECT_NEAR(widest_angular_gap(wrap), 3.0, 1e-12);
  std::vector<double> arc = {-0.1, 0.1, 0.0};  // a short arc: the rest of the turn is the gap
  EXPECT_NEAR(widest_angular_gap(arc), 2.0 * pi - 0.2, 1e-12);
  std::vector<double> one = {1.0};
  EXPECT_NEAR(widest_angular_gap(one), 2.0 * pi, 1e-12);
}

}  // namespace
}  // namespace cloudshape::geometry
