// Stage 3: vertex pursuit climbs to the vertices; one key-point per vertex.
#include <gtest/gtest.h>

#include "stage_fixtures.hpp"

namespace cloudshape::pipeline {
namespace {

using testing::stage;

std::vector<Point> box_corners(const synth::SolidSpec& spec) {
  std::vector<Point> out;
  const double l = spec.dimensions[0].second / 2, w = spec.dimensions[1].second / 2,
               h = spec.dimensions[2].second / 2;
  for (int a : {-1, 1})
    for (int b : {-1, 1})
      for (int c : {-1, 1}) out.push_back(spec.pose.to_world(Eigen::Vector3d(a * l, b * w, c * h)));
  return out;
}

TEST(Keypoints, PursuitClimbsToTheFarthestPoint) {
  // A ramp rising along x: the farthest point from the origin along any path is the end.
  PointList pts;
  for (int i = 0; i <= 100; ++i) pts.emplace_back(0.1 * i, 0.0, 0.0);
  const geometry::KdTree tree(pts);
  EXPECT_EQ(pursue_vertex(tree, 3, Point(-1, 0, 0), 5, 1000), 100u);
  EXPECT_EQ(pursue_vertex(tree, 3, Point(-1, 0, 0), 5, 2), 7u);  // the step budget holds
}

TEST(Keypoints, BoxHasOneKeyPointAtEachCorner) {
  const auto s = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  const auto corners = box_corners(s.spec);
  ASSERT_EQ(s.keypoints.keypoints.size(), 8u);
  std::vector<int> hits(8, 0);
  for (const auto& kp : s.keypoints.keypoints) {
    double best = 1e9;
    int which = -1;
    for (int c = 0; c < 8; ++c) {
      const double d = (s.pre.points[kp.index] - corners[c]).norm();
      if (d < best) best = d, which = c;
    }
    EXPECT_LT(best, 4.0 * s.pre.resolution);
    ++hits[which];
    EXPECT_EQ(kp.neighbourhood.size(), static_cast<std::size_t>(config::KeypointsConfig{}.neighbourhood));
  }
  for (int h : hits) EXPECT_EQ(h, 1);
}

TEST(Keypoints, ReferenceIsTheEnclosingSphereOfTheCloud) {
  const auto s = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  EXPECT_LT((s.keypoints.reference.center - s.spec.pose.center).norm(), 2.0 * s.pre.resolution);
  EXPECT_NEAR(s.keypoints.reference.radius, 0.5 * std::sqrt(14.0), 2.0 * s.pre.resolution);
}

TEST(Keypoints, ConeApexIsAKeyPoint) {
  const auto s = stage(synth::ShapeKind::cone, {1.0, 2.0});
  const Point apex = s.spec.pose.center + 2.0 * s.spec.pose.axes.row(0).transpose();
  double best = 1e9;
  for (const auto& kp : s.keypoints.keypoints) best = std::min(best, (s.pre.points[kp.index] - apex).norm());
  EXPECT_LT(best, 3.0 * s.pre.resolution);
}

}  // namespace
}  // namespace cloudshape::pipeline
