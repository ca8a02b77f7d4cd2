// Stage 4: key-point types from covariance, Table 3.1, the sphere test, degenerate clouds.
#include <gtest/gtest.h>

#include "stage_fixtures.hpp"

namespace cloudshape::pipeline {
namespace {

using testing::stage;

Keypoint whole(const PointList& pts, std::uint32_t index) {
  Keypoint kp;
  kp.index = index;
  for (std::uint32_t i = 0; i < pts.size(); ++i) kp.neighbourhood.push_back(i);
  return kp;
}

TEST(TypeKeypoint, FlatPatchIsABorder) {
  PointList pts{Point(0, 0, 0)};
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      if (i || j) pts.emplace_back(0.1 * i, 0.1 * j, 0.0);
  const auto t = type_keypoint(pts, whole(pts, 0), config::ClassifyConfig{});
  EXPECT_EQ(t.type, KeypointType::border);
  EXPECT_LT(t.curvature, 1e-9);
}

TEST(TypeKeypoint, CubeCornerIsACornerAndARidgeIsAnEdge) {
  PointList corner{Point(0, 0, 0)}, ridge{Point(0, 0, 0)};
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      if (i == 0 && j == 0) continue;
      corner.emplace_back(0.0, -0.1 * i, -0.1 * j);
      corner.emplace_back(-0.1 * i, 0.0, -0.1 * j);
      corner.emplace_back(-0.1 * i, -0.1 * j, 0.0);
    }
  // Two faces meeting at a right angle along the z axis, the key-point mid-ridge.
  for (int i = 0; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) {
      if (i == 0 && j == 0) continue;
      ridge.emplace_back(-0.1 * i, 0.0, 0.1 * j);
      if (i) ridge.emplace_back(0.0, -0.1 * i, 0.1 * j);
    }
  const config::ClassifyConfig cfg;
  const auto c = type_keypoint(corner, whole(corner, 0), cfg);
  const auto r = type_keypoint(ridge, whole(ridge, 0), cfg);
  EXPECT_EQ(c.type, KeypointType::corner) << c.gap_degrees;
  EXPECT_EQ(r.type, KeypointType::edge) << r.gap_degrees;
  EXPECT_NEAR(r.gap_degrees, 180.0, 10.0);
  EXPECT_GT(c.gap_degrees, 240.0);
}

TEST(ShapeFromKeypoints, Table31) {
  EXPECT_EQ(shape_from_keypoints({0, 12, 0}), Shape::cylinder);
  EXPECT_EQ(shape_from_keypoints({1, 10, 0}), Shape::cone);
  EXPECT_EQ(shape_from_keypoints({4, 0, 0}), Shape::tetrahedron);
  EXPECT_EQ(shape_from_keypoints({8, 0, 0}), Shape::box);
  EXPECT_EQ(shape_from_keypoints({10, 0, 0}), Shape::pentagonal_prism);
  EXPECT_EQ(shape_from_keypoints({6, 0, 0}), Shape::unknown);
  EXPECT_EQ(shape_from_keypoints({0, 0, 0}), Shape::unknown);
}

TEST(Classify, SphereTestAndCornerCountsOnSolids) {
  const auto sphere = stage(synth::ShapeKind::sphere, {1.0});
  EXPECT_TRUE(sphere.classification.sphere_test);
  EXPECT_EQ(sphere.classification.shape, Shape::sphere);
  const auto box = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  EXPECT_FALSE(box.classification.sphere_test);
  EXPECT_EQ(box.classification.shape, Shape::box);
  ASSERT_FALSE(box.classification.candidates.empty());
  EXPECT_EQ(box.classification.candidates.front(), Shape::box);
  EXPECT_GT(box.classification.face_fraction, 0.95);
  const auto cylinder = stage(synth::ShapeKind::cylinder, {1.0, 3.0});
  EXPECT_EQ(cylinder.classification.counts.corner, 0);
  EXPECT_GT(cylinder.classification.counts.edge, 0);
  EXPECT_EQ(cylinder.classification.shape, Shape::cylinder);
}

TEST(Classify, DegenerateCloudsHaveNoCandidateAndSayWhy) {
  const config::ClassifyConfig cfg;
  auto reason_for = [&](const PointList& pts, double res) {
    const auto c = classify_cloud(pts, PlaneSegmentation{}, KeypointSet{}, res, cfg);
    EXPECT_TRUE(c.candidates.empty());
    return c.reason;
  };
  PointList plane, line, same(40, Point(1, 2, 3));
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) plane.emplace_back(0.1 * i, 0.1 * j, 0.5 * (0.1 * i) - 0.1 * j);
  for (int i = 0; i < 50; ++i) line.emplace_back(0.1 * i, 0.2 * i, 0.3 * i);
  EXPECT_EQ(reason_for(plane, 0.1), "all points coplanar");
  EXPECT_EQ(reason_for(line, 0.1), "all points collinear");
  EXPECT_EQ(reason_for(same, 0.0), "all points coincide");
  EXPECT_NE(reason_for(PointList{Point(0, 0, 0), Point(1, 0, 0)}, 1.0).find("too few points"),
            std::string::npos);
}

}  // namespace
}  // namespace cloudshape::pipeline
