// Least-squares plane fit on noisy planes, plane through three points, intersections.
#include <gtest/gtest.h>

#include <random>

#include "geometry/plane.hpp"

namespace cloudshape::geometry {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(PlaneFit, NoisyPlaneRecoversNormalAndOffset) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-10, 10);
  std::normal_distribution<double> noise(0.0, 0.05);  // 0.25% of the patch size
  const Eigen::Vector3d n = Eigen::Vector3d(2, -1, 0.5).normalized();
  const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
  const Point origin(3, 4, -5);
  PointList pts;
  std::vector<std::uint32_t> idx;
  for (int i = 0; i < 5000; ++i) {
    pts.push_back(origin + u(rng) * a + u(rng) * b + noise(rng) * n);
    idx.push_back(i);
  }
  const Plane p = fit_plane_least_squares(pts, idx);
  EXPECT_LT(std::acos(std::min(1.0, std::abs(p.normal.dot(n)))), 0.1 * kDeg);
  EXPECT_LT(std::abs(p.signed_distance(origin)), 0.01);
}

TEST(PlaneThrough, ThreePointsAndCollinearRejection) {
  const auto p = plane_through(Point(0, 0, 1), Point(1, 0, 1), Point(0, 1, 1));
  ASSERT_TRUE(p);
  EXPECT_NEAR(std::abs(p->normal.z()), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(p->signed_distance(Point(5, 5, 1))), 0.0, 1e-12);
  EXPECT_FALSE(plane_through(Point(0, 0, 0), Point(1, 1, 1), Point(2, 2, 2)));
}

TEST(PlaneIntersection, TwoFacesOfABoxMeetAlongTheirEdge) {
  const Plane top{Eigen::Vector3d::UnitZ(), -2.0};  // z = 2
  const Plane side{Eigen::Vector3d::UnitX(), -1.0};  // x = 1
  const auto line = intersect_planes(top, side);
  ASSERT_TRUE(line);
  EXPECT_NEAR(std::abs(line->direction.y()), 1.0, 1e-12);
  EXPECT_NEAR(line->point.x(), 1.0, 1e-12);
  EXPECT_NEAR(line->point.z(), 2.0, 1e-12);
  EXPECT_FALSE(intersect_planes(top, Plane{Eigen::Vector3d::UnitZ(), 1.0}));
}

TEST(PlaneIntersection, ThreeFacesMeetAtTheCorner) {
  const auto corner = intersect_three_planes(Plane{Eigen::Vector3d::UnitX(), -1},
                                             Plane{Eigen::Vector3d::UnitY(), -2},
                                             Plane{Eigen::Vector3d::UnitZ(), -3});
  ASSERT_TRUE(corner);
  EXPECT_LT((*corner - Point(1, 2, 3)).norm(), 1e-12);
}

}  // namespace
}  // namespace cloudshape::geometry
