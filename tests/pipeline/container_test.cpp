// Solids seen from their hollow side (pipeline/container.hpp): a bowl's inside seen over its rim
// is the container's envelope cylinder when the sensor is known, a ball seen from outside stays one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/preprocess.hpp"
#include "pipeline/solve.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kRadius = 0.08;
const Point kCentre(0.05, -0.03, 0.9);  // the sensor at the origin looks along +z at it

// Evenly spread points of the sphere's half facing +z (away from the sensor: a bowl's inside
// seen over its rim) or -z (towards it: a ball's front).
PointList hemisphere(bool far_half, std::size_t count) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gauss(0.0, 1.0);
  PointList out;
  while (out.size() < count) {
    Eigen::Vector3d d(gauss(rng), gauss(rng), gauss(rng));
    d.normalize();
    if ((d.z() > 0.0) == far_half) out.push_back(kCentre + kRadius * d);
  }
  return out;
}

ObjectResult recognise(const PointList& raw, const std::optional<Point>& viewpoint) {
  const config::PipelineConfig cfg;
  const auto pre = preprocess_cloud(raw, cfg.preprocess);
  const auto planes = segment_planes(pre.points, pre.resolution, cfg.planes);
  const auto kp = find_keypoints(pre.points, planes, pre.resolution, cfg.keypoints);
  const auto cls = classify_cloud(pre.points, planes, kp, pre.resolution, cfg.classify);
  return solve_object(pre.points, planes, kp, cls, pre.resolution, cfg.solve, nullptr, viewpoint);
}

double dimension(const ObjectResult& r, const std::string& name) {
  for (const auto& [n, v] : r.dimensions)
    if (n == name) return v;
  ADD_FAILURE() << "no " << name;
  return 0.0;
}

// Rim radius and depth within 3% (the envelope reaches the 99.5% quantile of the points).
TEST(Container, BowlSeenOverItsRimIsItsEnvelopeCylinder) {
  const PointList bowl = hemisphere(true, 12000);
  const auto r = recognise(bowl, Point::Zero());
  ASSERT_EQ(r.shape, "cylinder") << r.reason;
  EXPECT_NEAR(dimension(r, "radius"), kRadius, 0.03 * kRadius);
  EXPECT_NEAR(dimension(r, "height"), kRadius, 0.03 * kRadius);
  EXPECT_LT(std::abs(r.axes.row(0).dot(Eigen::Vector3d::UnitZ())), 1.0 + 1e-9);
  EXPECT_GT(std::abs(r.axes.row(0).dot(Eigen::Vector3d::UnitZ())), std::cos(3.0 * 3.14159265358979 / 180.0));
  EXPECT_TRUE(r.partial);
}

// Without a sensor position the same points are a spherical cap like any other.
TEST(Container, WithoutAViewpointTheCapIsASphere) {
  const auto r = recognise(hemisphere(true, 12000), std::nullopt);
  ASSERT_EQ(r.shape, "sphere") << r.reason;
  EXPECT_NEAR(dimension(r, "radius"), kRadius, 0.01 * kRadius);
}

TEST(Container, BallSeenFromOutsideStaysASphere) {
  const auto r = recognise(hemisphere(false, 12000), Point::Zero());
  ASSERT_EQ(r.shape, "sphere") << r.reason;
  EXPECT_NEAR(dimension(r, "radius"), kRadius, 0.01 * kRadius);
}

}  // namespace
}  // namespace cloudshape::pipeline
