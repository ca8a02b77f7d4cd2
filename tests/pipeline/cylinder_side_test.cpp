// How much of a fitted cylinder its points show on its side (detail::cylinder_side_share): a can
// seen over its lid and side, against a flat face its cap's circle holds.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/solid_checks.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 0.002;
constexpr std::size_t kSamples = 4000;

// A cylinder of radius 4 cm and height 10 cm, its axis along z, centred at the origin.
FittedSolid can() {
  FittedSolid s;
  s.shape = Shape::cylinder;
  s.dimensions = {{"radius", 0.04}, {"height", 0.1}};
  s.axes = detail::frame_from_axis(Eigen::Vector3d::UnitZ());
  return s;
}

// `n` points of the lid (z = 5 cm) on a polar grid filling the disc evenly.
PointList lid(std::size_t rings, std::size_t per_ring) {
  PointList out;
  for (std::size_t r = 0; r < rings; ++r) {
    const double radius =
        0.04 * std::sqrt((static_cast<double>(r) + 0.5) / static_cast<double>(rings));
    for (std::size_t k = 0; k < per_ring; ++k) {
      const double a = 2.0 * kPi * static_cast<double>(k) / static_cast<double>(per_ring);
      out.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.05);
    }
  }
  return out;
}

TEST(CylinderSide, TheSideSeenHoldsItsShareAndTheLidsRimIsTheLids) {
  PointList points = lid(20, 50);  // 1 000 lid points
  // 1 000 on the front half of the side, from 1 cm under the lid to its bottom.
  for (std::size_t i = 0; i < 1000; ++i) {
    const double a = kPi * static_cast<double>(i % 50) / 49.0;
    const double z = 0.04 - 0.09 * static_cast<double>(i / 50) / 19.0;
    points.emplace_back(0.04 * std::cos(a), 0.04 * std::sin(a), z);
  }
  EXPECT_NEAR(detail::cylinder_side_share(points, can(), kTolerance, kSamples), 0.5, 0.03);
  // The lid alone: its outermost ring lies on the side's radius, but on the cap's plane.
  EXPECT_EQ(detail::cylinder_side_share(lid(20, 50), can(), kTolerance, kSamples), 0.0);
}

TEST(CylinderSide, AFlatTriangleInTheCapsCircleHasNoSide) {
  // A triangle inscribed in the lid's circle, its corners on the rim.
  PointList triangle;
  const Eigen::Vector3d a(0.04, 0.0, 0.05), b(-0.02, 0.0346, 0.05), c(-0.02, -0.0346, 0.05);
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; i + j <= 40; ++j)
      triangle.push_back(a + (b - a) * (i / 40.0) + (c - a) * (j / 40.0));
  EXPECT_EQ(detail::cylinder_side_share(triangle, can(), kTolerance, kSamples), 0.0);
}

TEST(CylinderSide, OtherSolidsHaveNone) {
  FittedSolid box = can();
  box.shape = Shape::box;
  EXPECT_EQ(detail::cylinder_side_share(lid(5, 10), box, kTolerance, kSamples), 0.0);
  EXPECT_EQ(detail::cylinder_side_share({}, can(), kTolerance, kSamples), 0.0);
}

}  // namespace
}  // namespace cloudshape::pipeline
