// rays_through_solid and returns_about: rays crossing a solid and returning on it, behind it or in
// front of it; grazing rays; the returns gathered about an object.
#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/free_space.hpp"

namespace cloudshape::pipeline {
namespace {

const Point kSensor = Point::Zero();

// A ball of radius 1 centred 10 ahead of the sensor.
double ball(const Point& p) { return (p - Point(0.0, 0.0, 10.0)).norm() - 1.0; }

// The point at `range` along the ray towards (x, y, 10).
Point along(double x, double y, double range) { return range * Point(x, y, 10.0).normalized(); }

TEST(RaysThroughSolid, ReturnsOnTheNearSideCrossButDoNotPassThrough) {
  PointList returns;
  for (double x = -0.5; x <= 0.5; x += 0.1) {
    const Point dir = Point(x, 0.0, 10.0).normalized();
    // Where the ray meets the ball: |t dir - c|^2 = 1.
    const double b = dir.z() * 10.0;
    const double t = b - std::sqrt(b * b - 99.0);
    returns.push_back(t * dir);
  }
  const RaysThroughSolid rays =
      rays_through_solid(returns, kSensor, ball, Point(0.0, 0.0, 10.0), 1.0, 0.05);
  EXPECT_EQ(rays.crossing, returns.size());
  EXPECT_EQ(rays.through, 0u);
}

TEST(RaysThroughSolid, ReturnsFromAWallBehindPassThrough) {
  PointList returns;
  for (double x = -0.5; x <= 0.5; x += 0.1) returns.push_back(along(x, 0.0, 20.0));
  const RaysThroughSolid rays =
      rays_through_solid(returns, kSensor, ball, Point(0.0, 0.0, 10.0), 1.0, 0.05);
  EXPECT_EQ(rays.crossing, returns.size());
  EXPECT_EQ(rays.through, returns.size());
}

TEST(RaysThroughSolid, ReturnsFromAnOccluderInFrontDoNotPassThrough) {
  PointList returns;
  for (double x = -0.5; x <= 0.5; x += 0.1) returns.push_back(along(x, 0.0, 5.0));
  const RaysThroughSolid rays =
      rays_through_solid(returns, kSensor, ball, Point(0.0, 0.0, 10.0), 1.0, 0.05);
  EXPECT_EQ(rays.crossing, returns.size());
  EXPECT_EQ(rays.through, 0u);
}

TEST(RaysThroughSolid, RaysBesideOrGrazingTheSolidCountForNeither) {
  PointList returns;
  // Beside the ball (its silhouette is 0.1 rad wide about the axis): x = 2 at 10 is 0.2 rad off.
  returns.push_back(along(2.0, 0.0, 20.0));
  returns.push_back(along(0.0, -3.0, 20.0));
  // Grazing its rim: the ray passes 0.99 from the centre, so at most 0.01 inside, within the depth.
  returns.push_back(along(0.99 * 10.0 / std::sqrt(100.0 - 0.99 * 0.99), 0.0, 20.0));
  const RaysThroughSolid rays =
      rays_through_solid(returns, kSensor, ball, Point(0.0, 0.0, 10.0), 1.0, 0.05);
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
