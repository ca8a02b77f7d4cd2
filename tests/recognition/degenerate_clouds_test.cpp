// Readable clouds with no solid in them give `unknown` with a reason, never an invented solid.
#include <gtest/gtest.h>

#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape {
namespace {

const pipeline::ObjectResult& only_object(const pipeline::RecognitionResult& r) {
  EXPECT_EQ(r.objects.size(), 1u);
  return r.objects.front();
}

void expect_unknown_because(const PointList& cloud, const std::string& reason_part) {
  const auto r = pipeline::recognize_cloud(cloud, config::PipelineConfig{}, "degenerate");
  const auto& o = only_object(r);
  EXPECT_EQ(o.shape, "unknown");
  EXPECT_TRUE(o.dimensions.empty());
  EXPECT_NE(o.reason.find(reason_part), std::string::npos) << o.reason;
}

TEST(DegenerateClouds, OnePointAndThreePoints) {
  expect_unknown_because({Point(1, 2, 3)}, "too few points");
  expect_unknown_because({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)}, "too few points");
}

TEST(DegenerateClouds, OneRepeatedPoint) {
  expect_unknown_because(PointList(5000, Point(4, 5, 6)), "all points coincide");
}

TEST(DegenerateClouds, AllCollinear) {
  PointList line;
  for (int i = 0; i < 5000; ++i) line.emplace_back(0.01 * i, 0.02 * i, -0.03 * i);
  expect_unknown_because(line, "collinear");
}

TEST(DegenerateClouds, AllCoplanarEvenWithSensorNoise) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> noise(0.0, 0.0005);
  const Eigen::Vector3d n = Eigen::Vector3d(1, 1, 2).normalized();
  const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
  PointList plane;
  for (int i = 0; i < 20000; ++i) plane.push_back(u(rng) * a + u(rng) * b + noise(rng) * n);
  expect_unknown_because(plane, "coplanar");
}

TEST(DegenerateClouds, RandomVolumeIsNoSolid) {
  // Points filling a cube's volume lie on no surface: nothing explains half of them.
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> u(-1, 1);
  PointList fog;
  for (int i = 0; i < 20000; ++i) fog.emplace_back(u(rng), u(rng), u(rng));
  const auto r = pipeline::recognize_cloud(fog, config::PipelineConfig{}, "fog");
  EXPECT_EQ(only_object(r).shape, "unknown");
}

}  // namespace
}  // namespace cloudshape
