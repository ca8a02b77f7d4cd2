// The oriented bounding box: every point inside, tight on rotated boxes and flat sets.
#include "geometry/oriented_box.hpp"

#include <gtest/gtest.h>

#include <random>

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

TEST(OrientedBox, EmptyAndSinglePoint) {
  EXPECT_EQ(oriented_bounding_box({}).size, Eigen::Vector3d::Zero());
  const OrientedBox one = oriented_bounding_box({Point(1, 2, 3)});
  EXPECT_EQ(one.size, Eigen::Vector3d::Zero());
  EXPECT_LT((one.center - Point(1, 2, 3)).norm(), 1e-12);
}

}  // namespace
}  // namespace cloudshape::geometry
