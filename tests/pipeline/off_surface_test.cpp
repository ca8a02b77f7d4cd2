// How much of its points a solid encloses without following them (detail::off_surface_share): a
// noisy ball's own points, strays scattered through it, and a squashed ball inside it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/kdtree.hpp"
#include "pipeline/solid_checks.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr std::size_t kPoints = 4000;  // spacing about 0.056 on the unit sphere
constexpr double kTolerance = 0.1;     // two spacings, as solve's inlier_distance
constexpr double kFar = 1.5 * kTolerance;

FittedSolid unit_ball() {
  FittedSolid s;
  s.shape = Shape::sphere;
  s.dimensions = {{"radius", 1.0}};
  s.signed_distance = [](const Point& p) { return p.norm() - 1.0; };
  return s;
}

// Evenly spread points (a Fibonacci lattice) on the ellipsoid of semi-axes 1, 1 and `c`, each
// moved by Gaussian noise of `sigma` along every axis.
PointList spheroid(double c, double sigma) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, sigma);
  PointList out;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < kPoints; ++i) {
    const double z = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(kPoints);
    const double r = std::sqrt(1.0 - z * z), a = golden * static_cast<double>(i);
    out.emplace_back(r * std::cos(a) + noise(rng), r * std::sin(a) + noise(rng),
                     c * z + noise(rng));
  }
  return out;
}

double share(const PointList& points) {
  const geometry::KdTree tree(points);
  return detail::off_surface_share(points, tree, unit_ball(), kFar, kTolerance, kPoints);
}

TEST(OffSurfaceShare, ABallsOwnNoisyPointsLieOnIt) {
  // Noise of a third of the tolerance: about 1 point in 3 000 lies beyond 1.5 tolerances.
  EXPECT_LT(share(spheroid(1.0, kTolerance / 3.0)), 0.002);
}

TEST(OffSurfaceShare, StraysScatteredThroughTheInsideDoNotCount) {
  PointList points = spheroid(1.0, kTolerance / 3.0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.75, 0.75);
  for (int i = 0; i < 200; ++i)
    points.emplace_back(u(rng), u(rng), u(rng));  // 5%, about 0.25 apart
  // Only the few strays that happen to lie within the tolerance of another count.
  EXPECT_LT(share(points), 0.01);
}

TEST(OffSurfaceShare, ASquashedBallInsideIsASurfaceItDoesNotFollow) {
  // Semi-axis 0.6 along z: the caps lie up to 0.4 (four tolerances) inside the unit ball; the
  // points more than 0.15 inside are those with |z| above about 0.55 of the height, a third.
  const double s = share(spheroid(0.6, kTolerance / 3.0));
  EXPECT_GT(s, 0.25);
  EXPECT_LT(s, 0.45);
}

}  // namespace
}  // namespace cloudshape::pipeline
