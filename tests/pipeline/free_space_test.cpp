// rays_through_solid and returns_about: rays crossing a solid and returning on it, behind it or in
// front of it; grazing rays; the returns gathered about an object.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/free_space.hpp"

namespace cloudshape::pipeline {
namespace {

const Point kSensor = Point::Zero();
const Point kCentre(0.0, 0.0, 10.0);

// A ball of radius 1 centred 10 ahead of the sensor.
double ball(const Point& p) { return (p - kCentre).norm() - 1.0; }

// The point at `range` along the ray towards (x, y, 10).
Point along(double x, double y, double range) { return range * Point(x, y, 10.0).normalized(); }

RaysThroughSolid through_ball(const PointList& returns) {
  return rays_through_solid(returns, kSensor, ball, kCentre, 1.0, 0.05);
}

// Eleven rays across the ball's middle (x from -0.5 to 0.5 at z = 10), each returning at `range`,
// or where it meets the ball for a range of 0.
PointList fan(double range) {
  PointList returns;
  for (int i = -5; i <= 5; ++i) {
    const Point dir = Point(0.1 * i, 0.0, 10.0).normalized();
    // Where the ray meets the ball: |t dir - c|^2 = 1.
    const double b = dir.dot(kCentre);
    returns.push_back((range > 0.0 ? range : b - std::sqrt(b * b - 99.0)) * dir);
  }
  return returns;
}

TEST(RaysThroughSolid, ReturnsOnTheNearSideCrossButDoNotPassThrough) {
  const RaysThroughSolid rays = through_ball(fan(0.0));
  EXPECT_EQ(rays.crossing, 11u);
  EXPECT_EQ(rays.through, 0u);
}

TEST(RaysThroughSolid, ReturnsFromAWallBehindPassThrough) {
  const RaysThroughSolid rays = through_ball(fan(20.0));
  EXPECT_EQ(rays.crossing, 11u);
  EXPECT_EQ(rays.through, 11u);
}

TEST(RaysThroughSolid, ReturnsFromAnOccluderInFrontDoNotPassThrough) {
  const RaysThroughSolid rays = through_ball(fan(5.0));
  EXPECT_EQ(rays.crossing, 11u);
  EXPECT_EQ(rays.through, 0u);
}

TEST(RaysThroughSolid, RaysBesideOrGrazingTheSolidCountForNeither) {
  PointList returns;
  // Beside the ball (its silhouette is 0.1 rad wide about the axis): x = 2 at 10 is 0.2 rad off.
  returns.push_back(along(2.0, 0.0, 20.0));
  returns.push_back(along(0.0, -3.0, 20.0));
  // Grazing its rim: the ray passes 0.99 from the centre, so at most 0.01 inside, within the depth.
  returns.push_back(along(0.99 * 10.0 / std::sqrt(100.0 - 0.99 * 0.99), 0.0, 20.0));
  const RaysThroughSolid rays = through_ball(returns);
  EXPECT_EQ(rays.crossing, 0u);
  EXPECT_EQ(rays.through, 0u);
}

TEST(ReturnsAbout, GathersTheReturnsWithinTheFactorOfTheObjectsAngularRadius) {
  // An object 0.1 rad wide about the +z axis, seen from the origin.
  const PointList object{along(1.0, 0.0, 10.0), along(-1.0, 0.0, 10.0), along(0.0, 1.0, 10.0),
                         along(0.0, -1.0, 10.0)};
  PointList frame = object;
  frame.push_back(along(2.5, 0.0, 30.0));   // 0.245 rad off: within 3 x 0.1
  frame.push_back(along(0.0, -3.5, 30.0));  // 0.337 rad off: beyond
  frame.push_back(Point(0.0, 0.0, -10.0));  // behind the sensor
  const PointList about = returns_about(frame, object, kSensor, 3.0);
  ASSERT_EQ(about.size(), 5u);
  EXPECT_EQ(about.back(), frame[4]);
  EXPECT_TRUE(returns_about(frame, {}, kSensor, 3.0).empty());
}

}  // namespace
}  // namespace cloudshape::pipeline
