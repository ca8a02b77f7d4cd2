// Pose conventions of INTERFACE.md: where the centre is and which way the axes point.
#include "surface_oracle.hpp"
#include "synth/pose.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

Eigen::Vector3d centroid(const PointList& points) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& p : points) c += p;
  return c / static_cast<double>(points.size());
}

void expect_rotation(const Eigen::Matrix3d& axes) {
  EXPECT_TRUE((axes * axes.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  EXPECT_NEAR(axes.determinant(), 1.0, 1e-12);
}

TEST(PoseConventions, CentreIsTheCentroidForCentredSolids) {
  std::mt19937_64 rng(3);
  for (ShapeKind kind : {ShapeKind::box, ShapeKind::sphere, ShapeKind::tetrahedron,
                         ShapeKind::pentagonal_prism, ShapeKind::cylinder}) {
    const SolidSpec spec = random_solid(kind, rng, 10.0);
    const auto c = centroid(sample_solid_surface(spec, 400000, rng));
    EXPECT_LT((c - spec.pose.center).norm(), 0.01 * 10.0) << to_string(kind);
  }
}

TEST(PoseConventions, ConeCentreIsBaseCentreAndFirstAxisPointsToApex) {
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 5; ++trial) {
    const SolidSpec spec = random_solid(ShapeKind::cone, rng, 8.0);
    const double r = dimension(spec, "radius"), h = dimension(spec, "height");
    const Eigen::Vector3d axis = spec.pose.axes.row(0).transpose();
    const Eigen::Vector3d apex = spec.pose.center + h * axis;
    const auto points = sample_solid_surface(spec, 100000, rng);
    PointList base;
    for (const auto& p : points) {
      const double along = (p - spec.pose.center).dot(axis);
      EXPECT_GE(along, -1e-9);
      EXPECT_LE(along, h + 1e-9);
      if (std::abs(along) < 1e-9) base.push_back(p);
      // Near the top every point is near the apex: the cone narrows towards +axes[0].
      if (along > 0.99 * h) {
        EXPECT_LT((p - apex).norm(), 0.011 * std::hypot(r, h));
      }
    }
    ASSERT_GT(base.size(), 100u);
    EXPECT_LT((centroid(base) - spec.pose.center).norm(), 0.02 * r);
  }
}

TEST(PoseConventions, RandomPoseAxesAreRightHandedOrthonormal) {
  std::mt19937_64 rng(5);
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Pose pose = random_pose(rng, 2.0);
    expect_rotation(pose.axes);
    EXPECT_LE(pose.center.cwiseAbs().maxCoeff(), 2.0);
    sum += pose.axes;
  }
  // A uniform rotation has zero mean matrix; a biased generator would not.
  EXPECT_LT((sum / n).cwiseAbs().maxCoeff(), 0.03);
}

TEST(PoseConventions, RandomSolidsHaveSensibleProportionsAndSortedBoxes) {
  std::mt19937_64 rng(6);
  for (int trial = 0; trial < 200; ++trial)
    for (ShapeKind kind : all_shape_kinds()) {
      const SolidSpec spec = random_solid(kind, rng, 12.0);
      expect_rotation(spec.pose.axes);
      EXPECT_NEAR(characteristic_size(spec), 12.0, 1e-9) << to_string(kind);
      ASSERT_EQ(spec.dimensions.size(), dimension_names(kind).size());
      for (std::size_t i = 0; i < spec.dimensions.size(); ++i)
        EXPECT_EQ(spec.dimensions[i].first, dimension_names(kind)[i]);
      if (kind == ShapeKind::box) {
        const double l = dimension(spec, "length"), w = dimension(spec, "width"),
                     h = dimension(spec, "height");
        EXPECT_GE(l, w);
        EXPECT_GE(w, h);
        EXPECT_LE(l / h, 3.0 + 1e-9);
      }
      if (kind == ShapeKind::cone || kind == ShapeKind::cylinder) {
        const double ratio = dimension(spec, "height") / dimension(spec, "radius");
        EXPECT_GE(ratio, 0.5 - 1e-9);
        EXPECT_LE(ratio, 4.0 + 1e-9);
      }
    }
}

TEST(PoseConventions, BoxAxesRunAlongLengthWidthHeight) {
  std::mt19937_64 rng(7);
  // Unsorted input: make_solid sorts and must carry the axes along.
  const SolidSpec spec = make_solid(ShapeKind::box, {2.0, 9.0, 5.0}, random_pose(rng, 3.0));
  expect_rotation(spec.pose.axes);
  EXPECT_EQ(dimension(spec, "length"), 9.0);
  EXPECT_EQ(dimension(spec, "width"), 5.0);
  EXPECT_EQ(dimension(spec, "height"), 2.0);
  const auto points = sample_solid_surface(spec, 20000, rng);
  for (int k = 0; k < 3; ++k) {
    double lo = 1e300, hi = -1e300;
    for (const auto& p : points) {
      const double t = (p - spec.pose.center).dot(spec.pose.axes.row(k).transpose());
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    EXPECT_NEAR(hi - lo, spec.dimensions[k].second, 0.02) << "axis " << k;
  }
}

}  // namespace
}  // namespace cloudshape::synth
