// Which fitted solids are one answer (detail::same_kind): one family (shape.hpp), except a cylinder
// and a frustum that leans and narrows beyond what the tolerance hides.
#include <gtest/gtest.h>

#include "pipeline/solid_checks.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kTolerance = 0.01;  // the verification's band, two resolutions
constexpr double kParallelDegrees = 10.0;

FittedSolid solid(Shape shape, std::vector<std::pair<std::string, double>> dimensions) {
  FittedSolid s;
  s.shape = shape;
  s.dimensions = std::move(dimensions);
  return s;
}

const FittedSolid kCylinder = solid(Shape::cylinder, {{"radius", 0.04}, {"height", 0.15}});

TEST(SolidKind, AFrustumNarrowingWithinTheToleranceIsACylindersKin) {
  // 15 mm over 15 cm leans 5.7 degrees; 3 cm over 15 cm leans 11 degrees but within 2 tolerances.
  EXPECT_TRUE(detail::same_kind(
      kCylinder, solid(Shape::frustum, {{"radius", 0.05}, {"top_radius", 0.035}, {"height", 0.15}}),
      kTolerance, kParallelDegrees));
  EXPECT_TRUE(detail::same_kind(
      kCylinder, solid(Shape::frustum, {{"radius", 0.03}, {"top_radius", 0.011}, {"height", 0.1}}),
      kTolerance, kParallelDegrees));
}

TEST(SolidKind, ABottlesSlightTaperIsACylindersKin) {
  // learn44's: 13 mm over 23 cm, 3 degrees, more than two tolerances of 3.3 mm.
  EXPECT_TRUE(detail::same_kind(
      kCylinder,
      solid(Shape::frustum, {{"radius", 0.047}, {"top_radius", 0.034}, {"height", 0.233}}), 0.00325,
      kParallelDegrees));
}

TEST(SolidKind, AFrustumLeaningAndNarrowingBeyondTheToleranceIsAnotherAnswer) {
  // A lying cone's frustum: 45 to 14 mm over 15 cm, 11.5 degrees, 31 mm against 24 mm.
  const FittedSolid tapered =
      solid(Shape::frustum, {{"radius", 0.0448}, {"top_radius", 0.0143}, {"height", 0.1527}});
  EXPECT_FALSE(detail::same_kind(kCylinder, tapered, 0.012, kParallelDegrees));
  EXPECT_FALSE(detail::same_kind(tapered, kCylinder, 0.012, kParallelDegrees));
  // A cone is the frustum's family whatever its taper.
  EXPECT_TRUE(detail::same_kind(solid(Shape::cone, {{"radius", 0.045}, {"height", 0.18}}), tapered,
                                0.012, kParallelDegrees));
}

TEST(SolidKind, OtherFamiliesStayApart) {
  EXPECT_FALSE(detail::same_kind(kCylinder, solid(Shape::cone, {{"radius", 0.04}, {"height", 0.1}}),
                                 kTolerance, kParallelDegrees));
  EXPECT_FALSE(detail::same_kind(kCylinder, solid(Shape::sphere, {{"radius", 0.04}}), kTolerance,
                                 kParallelDegrees));
  EXPECT_TRUE(detail::same_kind(solid(Shape::box, {}), solid(Shape::prism, {}), kTolerance,
                                kParallelDegrees));
}

}  // namespace
}  // namespace cloudshape::pipeline
