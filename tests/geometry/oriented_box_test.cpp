// The oriented bounding box: every point inside, tight on rotated boxes and flat sets.
#include "geometry/oriented_box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/convex_hull.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::geometry {
namespace {

// Points on the surface of an a x b x c box, rotated by `r` and moved to `at`.
PointList box_surface(const Eigen::Vector3d& dims, const Eigen::Matrix3d& r, const Eigen::Vector3d& at,
                      std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::uniform_int_distribution<int> face(0, 5);
  PointList out;
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d p(u(rng), u(rng), u(rng));
    const int f = face(rng);
    p[f / 2] = f % 2 ? 0.5 : -0.5;
    out.push_back(r * p.cwiseProduct(dims) + at);
  }
  return out;
}

void expect_contains(const OrientedBox& b, const PointList& points, double slack) {
  for (const Point& p : points) {
    const Eigen::Vector3d l = b.axes * (p - b.center);
    for (int k = 0; k < 3; ++k) ASSERT_LE(std::abs(l[k]), 0.5 * b.size[k] + slack);
  }
}

TEST(OrientedBox, RotatedBoxIsRecoveredTightly) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d at(10, -4, 2);
  const PointList pts = box_surface({6, 4, 1}, r, at, 20000, 1);
  const OrientedBox b = oriented_bounding_box(pts);
  expect_contains(b, pts, 1e-9);
  EXPECT_NEAR(b.size[0], 6.0, 0.02);
  EXPECT_NEAR(b.size[1], 4.0, 0.02);
  EXPECT_NEAR(b.size[2], 1.0, 0.02);
  EXPECT_LT((b.center - at).norm(), 0.02);
  EXPECT_NEAR(std::abs(b.axes.row(2).dot(r.col(2).transpose())), 1.0, 1e-4);
  EXPECT_NEAR(b.axes.determinant(), 1.0, 1e-12);
  EXPECT_LT((b.axes * b.axes.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
}

// A cube: its principal axes are undetermined, yet the box must still be the cube, not a
// rotated box around it (volume within 2%).
TEST(OrientedBox, CubeDoesNotDependOnPrincipalAxes) {
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.3, 1, 2).normalized()).toRotationMatrix();
  const PointList pts = box_surface({2, 2, 2}, r, Eigen::Vector3d::Zero(), 20000, 2);
  const OrientedBox b = oriented_bounding_box(pts);
  expect_contains(b, pts, 1e-9);
  EXPECT_LT(b.size.prod(), 8.0 * 1.02);
}

// A flat rectangle rotated in its plane: the box is the rectangle, thickness ~0.
TEST(OrientedBox, FlatRectangleGivesItsRectangle) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  PointList pts;
  for (int i = 0; i < 5000; ++i) pts.push_back(r * Eigen::Vector3d(5 * u(rng), 2 * u(rng), 0.0));
  const OrientedBox b = oriented_bounding_box(pts);
  expect_contains(b, pts, 1e-9);
  EXPECT_NEAR(b.size[0], 5.0, 0.02);
  EXPECT_NEAR(b.size[1], 2.0, 0.02);
  EXPECT_LT(b.size[2], 1e-9);
}

// The starts worked from side by side on a pool: the box of the serial search, to the bit (a
// cylinder-like set; with hints, three starts on two threads; without, the one start inline).
TEST(OrientedBox, APoolGivesTheSameBox) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586);
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  PointList pts;
  for (int i = 0; i < 6000; ++i) {
    const double a = angle(rng);
    pts.push_back(r * Eigen::Vector3d(2.0 * std::cos(a), 2.0 * std::sin(a), 3.0 * u(rng)));
  }
  const Eigen::Matrix3d hint = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  parallel::ThreadPool pool(2);
  for (const std::vector<Eigen::Matrix3d>& hints :
       {std::vector<Eigen::Matrix3d>{}, std::vector<Eigen::Matrix3d>{hint, r}}) {
    const OrientedBox serial = oriented_bounding_box(pts, hints);
    const OrientedBox split = oriented_bounding_box(pts, hints, 2000, &pool);
    EXPECT_EQ(split.center, serial.center) << hints.size();
    EXPECT_EQ(split.axes, serial.axes) << hints.size();
    EXPECT_EQ(split.size, serial.size) << hints.size();
  }
}

TEST(OrientedBox, EmptyAndSinglePoint) {
  EXPECT_EQ(oriented_bounding_box({}).size, Eigen::Vector3d::Zero());
  const OrientedBox one = oriented_bounding_box({Point(1, 2, 3)});
  EXPECT_EQ(one.size, Eigen::Vector3d::Zero());
  EXPECT_LT((one.center - Point(1, 2, 3)).norm(), 1e-12);
}

// Every edge's rectangle round every vertex, the first of least area: what
// detail::min_area_direction must give, bit for bit, from its caliper bounds.
Eigen::Vector2d scan_every_edge(const std::vector<Eigen::Vector2d>& hull) {
  Eigen::Vector2d best = Eigen::Vector2d::UnitX();
  double best_area = HUGE_VAL;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d e = hull[(i + 1) % hull.size()] - hull[i];
    if (!(e.norm() > 0.0)) continue;
    const Eigen::Vector2d u = e.normalized(), v(-u.y(), u.x());
    double ulo = HUGE_VAL, uhi = -HUGE_VAL, vlo = HUGE_VAL, vhi = -HUGE_VAL;
    for (const Eigen::Vector2d& q : hull) {
      ulo = std::min(ulo, q.dot(u)), uhi = std::max(uhi, q.dot(u));
      vlo = std::min(vlo, q.dot(v)), vhi = std::max(vhi, q.dot(v));
    }
    const double area = (uhi - ulo) * (vhi - vlo);
    if (area < best_area) best_area = area, best = u;
  }
  return best;
}

// Hulls of many vertices with near-equal rectangles (a circle's rim, exact and noisy), of random
// points, regular polygons whose rectangles tie exactly, slivers, repeated vertices, clockwise
// polygons, and stars.
TEST(OrientedBox, LeastAreaDirectionIsTheScanOfEveryEdge) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1e-3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::vector<Eigen::Vector2d>> hulls;
  for (int sides : {3, 4, 8, 12, 360, 2000}) {
    std::vector<Eigen::Vector2d> exact, noisy;
    for (int k = 0; k < sides; ++k) {
      const double a = 2.0 * 3.14159265358979323846 * k / sides;
      exact.emplace_back(std::cos(a), std::sin(a));
      noisy.emplace_back(std::cos(a) + noise(rng), std::sin(a) + noise(rng));
    }
    hulls.push_back(exact);
    hulls.push_back(convex_hull_2d(noisy));
  }
  for (int cloud = 0; cloud < 20; ++cloud) {
    std::vector<Eigen::Vector2d> pts;
    for (int k = 0; k < 500; ++k) pts.emplace_back(u(rng), (cloud % 4 == 0 ? 0.01 : 1.0) * u(rng));
    hulls.push_back(convex_hull_2d(pts));
  }
  std::vector<Eigen::Vector2d> repeated = hulls[2];
  repeated.insert(repeated.begin() + 3, repeated[3]);
  hulls.push_back(repeated);
  // Stars: not convex, so the calipers stop at points short of the extremes; the bounds are loose
  // and the areas are worked out for more edges, still the scan's answer.
  for (int star = 0; star < 6; ++star) {
    std::vector<Eigen::Vector2d> pts;
    const int tips = 5 + star;
    for (int k = 0; k < 2 * tips; ++k) {
      const double a = 3.14159265358979323846 * k / tips + 0.1 * star, r = k % 2 ? 0.3 + 0.1 * star : 1.0 + 0.2 * u(rng);
      pts.emplace_back(r * std::cos(a) * (1.0 + star), r * std::sin(a));
    }
    hulls.push_back(pts);
  }
  for (std::size_t from : {std::size_t{9}, std::size_t{12}, std::size_t{13}}) {
    std::vector<Eigen::Vector2d> clockwise = hulls[from];
    std::reverse(clockwise.begin(), clockwise.end());
    hulls.push_back(clockwise);
  }
  for (std::size_t h = 0; h < hulls.size(); ++h) {
    const Eigen::Vector2d want = scan_every_edge(hulls[h]);
    const Eigen::Vector2d got = detail::min_area_direction(hulls[h]);
    EXPECT_EQ(got.x(), want.x()) << "hull " << h << " of " << hulls[h].size();
    EXPECT_EQ(got.y(), want.y()) << "hull " << h << " of " << hulls[h].size();
  }
}

}  // namespace
}  // namespace cloudshape::geometry
