// The side-cylinder refinement (pipeline/cylinder_refine.hpp): from a start a few degrees and
// millimetres off, the front half of a noisy can's side gives back its axis and radius.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pipeline/cylinder_refine.hpp"

namespace cloudshape::pipeline::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Can {
  Point base = Point(0.1, 0.05, 0.8);
  Eigen::Vector3d axis = Eigen::Vector3d(0.1, -0.8, -0.55).normalized();
  double radius = 0.035;
  double height = 0.1;
};

// The side's half facing the sensor at the origin, with Gaussian noise `sigma` along the radius.
PointList front_half(const Can& can, std::size_t count, double sigma) {
  Eigen::Vector3d u = can.axis.unitOrthogonal();
  Eigen::Vector3d v = can.axis.cross(u);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi), along(0.0, can.height);
  std::normal_distribution<double> noise(0.0, sigma);
  PointList out;
  while (out.size() < count) {
    const double a = angle(rng);
    const Eigen::Vector3d radial = std::cos(a) * u + std::sin(a) * v;
    const Point p = can.base + along(rng) * can.axis + (can.radius + noise(rng)) * radial;
    if (radial.dot(-p) > 0.0) out.push_back(p);
  }
  return out;
}

std::vector<std::uint32_t> all(const PointList& points) {
  std::vector<std::uint32_t> out(points.size());
  for (std::uint32_t i = 0; i < out.size(); ++i) out[i] = i;
  return out;
}

// Spacing about 1.5 mm, noise a third of it, band 6 spacings as in config/pipeline.yaml. Axis
// within 0.5 degrees, radius within 2%, axis line within 5% of the radius of the true one.
TEST(CylinderRefine, TiltedOffsetStartConvergesToTheSide) {
  const Can can;
  const PointList points = front_half(can, 4000, 0.0005);
  const Eigen::Vector3d tilt = can.axis.unitOrthogonal();
  SideCylinder start;
  start.axis = (can.axis + std::tan(6.0 * kPi / 180.0) * tilt).normalized();
  start.on_axis = can.base + 0.5 * can.height * can.axis + 0.004 * can.axis.cross(tilt);
  start.radius = 0.9 * can.radius;
  const SideCylinder got = refine_side_cylinder(points, all(points), start, 6.0 * 0.0015, 15);
  EXPECT_LT(std::acos(std::min(1.0, std::abs(got.axis.dot(can.axis)))) * 180.0 / kPi, 0.5);
  EXPECT_NEAR(got.radius, can.radius, 0.02 * can.radius);
  const Eigen::Vector3d off = got.on_axis - can.base;
  EXPECT_LT((off - off.dot(can.axis) * can.axis).norm(), 0.05 * can.radius);
}

TEST(CylinderRefine, NoPointsNearTheStartKeepIt) {
  const Can can;
  const PointList points = front_half(can, 500, 0.0);
  SideCylinder start;
  start.axis = can.axis;
  start.on_axis = can.base + Eigen::Vector3d(0.5, 0.0, 0.0);
  start.radius = can.radius;
  const SideCylinder got = refine_side_cylinder(points, all(points), start, 0.005, 15);
  EXPECT_EQ(got.on_axis, start.on_axis);
  EXPECT_EQ(got.radius, start.radius);
}

// The front half covers about 180 degrees of arc; a flat face tangent to the cylinder (the same
// can's radius, points spread over a width of two radii) meets its side over a narrow arc only.
TEST(CylinderRefine, HalfASideCoversHalfTheArcATangentFaceLittle) {
  const Can can;
  const PointList half = front_half(can, 4000, 0.0);
  const SideCylinder truth{can.base, can.axis, can.radius};
  const double band = 2.0 * 0.0015;
  EXPECT_NEAR(side_arc_degrees(half, all(half), truth, band), 180.0, 20.0);
  const Eigen::Vector3d normal = can.axis.unitOrthogonal();
  const Eigen::Vector3d across = can.axis.cross(normal);
  PointList face;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j)
      face.push_back(can.base + can.radius * normal + (i / 59.0) * can.height * can.axis +
                     (j / 59.0 - 0.5) * 2.0 * can.radius * across);
  EXPECT_LT(side_arc_degrees(face, all(face), truth, band), 90.0);
}

}  // namespace
}  // namespace cloudshape::pipeline::detail
