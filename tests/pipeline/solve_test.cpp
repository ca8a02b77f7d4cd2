// Stage 5: each solid's dimensions and pose against the analytic truth (1% / 1 degree).
#include <gtest/gtest.h>

#include <string>

#include "pipeline/shape.hpp"
#include "pipeline/solve.hpp"
#include "stage_fixtures.hpp"

namespace cloudshape::pipeline {
namespace {

using testing::stage;

constexpr double kRelTol = 0.01;

ObjectResult solve(const testing::StagedCloud& s) {
  return solve_object(s.pre.points, s.planes, s.keypoints, s.classification, s.pre.resolution,
                      config::SolveConfig{});
}

void expect_dimensions(const ObjectResult& got, const synth::SolidSpec& truth) {
  ASSERT_EQ(got.dimensions.size(), truth.dimensions.size());
  for (std::size_t i = 0; i < got.dimensions.size(); ++i) {
    EXPECT_EQ(got.dimensions[i].first, truth.dimensions[i].first);
    EXPECT_NEAR(got.dimensions[i].second, truth.dimensions[i].second,
                kRelTol * truth.dimensions[i].second)
        << got.dimensions[i].first;
  }
}

double axis_angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool signed_axis) {
  const double c = signed_axis ? a.normalized().dot(b.normalized()) : std::abs(a.normalized().dot(b.normalized()));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

TEST(Solve, Box) {
  const auto s = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  const auto r = solve(s);
  ASSERT_EQ(r.shape, "box");
  expect_dimensions(r, s.spec);
  EXPECT_LT((r.center - s.spec.pose.center).norm(), 0.01 * 3.0);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(axis_angle_deg(r.axes.row(k), s.spec.pose.axes.row(k), false), 1.0) << "axis " << k;
  EXPECT_GT(r.confidence, 0.95);
}

TEST(Solve, Tetrahedron) {
  const auto s = stage(synth::ShapeKind::tetrahedron, {2.0});
  const auto r = solve(s);
  ASSERT_EQ(r.shape, "tetrahedron");
  expect_dimensions(r, s.spec);
  EXPECT_LT((r.center - s.spec.pose.center).norm(), 0.02);
}

TEST(Solve, PentagonalPrism) {
  const auto s = stage(synth::ShapeKind::pentagonal_prism, {1.0, 2.5});
  const auto r = solve(s);
  ASSERT_EQ(r.shape, "pentagonal_prism");
  expect_dimensions(r, s.spec);
  EXPECT_LT(axis_angle_deg(r.axes.row(0), s.spec.pose.axes.row(0), false), 1.0);
  EXPECT_LT((r.center - s.spec.pose.center).norm(), 0.025);
}

TEST(Solve, CylinderCentreIsTheAxisMidpoint) {
  const auto s = stage(synth::ShapeKind::cylinder, {1.0, 3.0});
  const auto r = solve(s);
  ASSERT_EQ(r.shape, "cylinder");
  expect_dimensions(r, s.spec);
  EXPECT_LT(axis_angle_deg(r.axes.row(0), s.spec.pose.axes.row(0), false), 1.0);
  EXPECT_LT((r.center - s.spec.pose.center).norm(), 0.03);
}

TEST(Solve, ConeAxisPointsFromBaseToApex) {
  const auto s = stage(synth::ShapeKind::cone, {1.0, 2.0});
  const auto r = solve(s);
  ASSERT_EQ(r.shape, "cone");
  expect_dimensions(r, s.spec);
  EXPECT_LT(axis_angle_deg(r.axes.row(0), s.spec.pose.axes.row(0), true), 1.0);
  EXPECT_LT((r.center - s.spec.pose.center).norm(), 0.02);  // centre of the base circle
}

TEST(Solve, Sphere) {
  const auto s = stage(synth::ShapeKind::sphere, {1.5});
  const auto r = solve(s);
  ASSERT_EQ(r.shape, "sphere");
  expect_dimensions(r, s.spec);
  EXPECT_LT((r.center - s.spec.pose.center).norm(), 0.015);
  EXPECT_NEAR(r.axes.determinant(), 1.0, 1e-9);
}

TEST(Solve, AxesAreOrthonormal) {
  for (auto kind : synth::all_shape_kinds()) {
    const auto s = stage(kind, kind == synth::ShapeKind::box ? std::vector<double>{3, 2, 1}
                               : synth::dimension_names(kind).size() == 2 ? std::vector<double>{1, 2}
                                                                           : std::vector<double>{1});
    const auto r = solve(s);
    EXPECT_LT((r.axes * r.axes.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-9)
        << synth::to_string(kind);
  }
}

// A lidar object on fewer scan lines than solid_min_scan_lines (5): only a sphere is taken as
// determined (two lines are two circles of it), so a box's points give unknown with the reason,
// while a sphere's are still a sphere; on five lines the box is a box again.
TEST(Solve, OnFewScanLinesOnlyASphereIsNamed) {
  const auto box = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  const auto solve_on = [](const testing::StagedCloud& s, std::uint32_t lines) {
    return solve_object(s.pre.points, s.planes, s.keypoints, s.classification, s.pre.resolution, config::SolveConfig{},
                        nullptr, std::nullopt, 1, lines);
  };
  for (std::uint32_t lines : {2u, 4u}) {
    const ObjectResult few = solve_on(box, lines);
    EXPECT_EQ(few.shape, "unknown");
    EXPECT_NE(few.reason.find(std::to_string(lines) + " scan lines"), std::string::npos)
        << few.reason;
  }
  EXPECT_EQ(solve_on(box, 5).shape, "box");
  const auto sphere = stage(synth::ShapeKind::sphere, {1.5});
  const ObjectResult ball = solve_on(sphere, 2);
  ASSERT_EQ(ball.shape, "sphere");
  expect_dimensions(ball, sphere.spec);
}

// A box is a four-sided prism, a pentagonal prism a five-sided one, a cylinder a frustum of equal
// radii and a cone one closed at its top: each pair explains the same points as one answer, while
// solids of different families that do so leave the object unknown (solve.ambiguity_rms_ratio).
TEST(Solve, SameFamilyIsAShapeAndItsGeneralisation) {
  EXPECT_TRUE(same_family(Shape::box, Shape::prism));
  EXPECT_TRUE(same_family(Shape::prism, Shape::pentagonal_prism));
  EXPECT_TRUE(same_family(Shape::cylinder, Shape::frustum));
  EXPECT_TRUE(same_family(Shape::frustum, Shape::cone));
  EXPECT_TRUE(same_family(Shape::sphere, Shape::sphere));
  EXPECT_FALSE(same_family(Shape::cylinder, Shape::cone));
  EXPECT_FALSE(same_family(Shape::cylinder, Shape::sphere));
  EXPECT_FALSE(same_family(Shape::box, Shape::pentagonal_prism));
  EXPECT_FALSE(same_family(Shape::box, Shape::frustum));
  EXPECT_FALSE(same_family(Shape::tetrahedron, Shape::prism));
}

// With a pool the candidates are fitted side by side, sharing the once-computed normals: the
// same solid, to the bit, as one after another.
TEST(Solve, APoolGivesTheSameResult) {
  parallel::ThreadPool pool(3);
  for (const auto& s : {stage(synth::ShapeKind::box, {3.0, 2.0, 1.0}), stage(synth::ShapeKind::cylinder, {1.0, 3.0}),
                        stage(synth::ShapeKind::cone, {1.0, 2.0}), stage(synth::ShapeKind::sphere, {1.5})}) {
    const ObjectResult serial = solve(s);
    const ObjectResult split = solve_object(s.pre.points, s.planes, s.keypoints, s.classification, s.pre.resolution,
                                            config::SolveConfig{}, nullptr, std::nullopt, 1, 0, &pool);
    ASSERT_EQ(split.shape, serial.shape);
    EXPECT_EQ(split.dimensions, serial.dimensions) << serial.shape;
    EXPECT_EQ(split.center, serial.center) << serial.shape;
    EXPECT_EQ(split.axes, serial.axes) << serial.shape;
    EXPECT_EQ(split.confidence, serial.confidence) << serial.shape;
  }
}

}  // namespace
}  // namespace cloudshape::pipeline
