// Stage 2: faces of polyhedra, caps versus tangent strips of curved solids, lines.
#include <gtest/gtest.h>

#include "stage_fixtures.hpp"

namespace cloudshape::pipeline {
namespace {

using testing::face_count;
using testing::stage;

TEST(Planes, BoxHasSixFacesAlongItsAxes) {
  const auto s = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  EXPECT_EQ(face_count(s.planes), 6);
  for (const auto& p : s.planes.planes) {
    if (!p.is_face) continue;
    double best = 0;
    for (int k = 0; k < 3; ++k) best = std::max(best, std::abs(p.plane.normal.dot(s.spec.pose.axes.row(k).transpose())));
    EXPECT_GT(best, std::cos(0.5 * 3.14159265 / 180.0));  // within half a degree of a box axis
    // Normals point away from the solid.
    EXPECT_GT(p.plane.normal.dot(s.pre.points[p.inliers.front()] - s.spec.pose.center), 0.0);
  }
}

TEST(Planes, BoxEdgesAreTheTwelveLines) {
  const auto s = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  EXPECT_EQ(s.planes.lines.size(), 12u);
  for (const auto& line : s.planes.lines) {
    // Each line runs along one box axis.
    double best = 0;
    for (int k = 0; k < 3; ++k) best = std::max(best, std::abs(line.line.direction.dot(s.spec.pose.axes.row(k).transpose())));
    EXPECT_GT(best, 0.999);
  }
}

TEST(Planes, CylinderCapsAreFacesAndItsSideIsNot) {
  const auto s = stage(synth::ShapeKind::cylinder, {1.0, 3.0});
  const Eigen::Vector3d axis = s.spec.pose.axes.row(0).transpose();
  int caps = 0;
  for (const auto& p : s.planes.planes) {
    if (p.is_face) {
      ++caps;
      EXPECT_GT(std::abs(p.plane.normal.dot(axis)), 0.9999);
    } else {
      // A tangent strip: its normal is perpendicular to the axis.
      EXPECT_LT(std::abs(p.plane.normal.dot(axis)), 0.05);
    }
  }
  EXPECT_EQ(caps, 2);
}

TEST(Planes, SphereHasNoFace) {
  const auto s = stage(synth::ShapeKind::sphere, {1.0});
  EXPECT_EQ(face_count(s.planes), 0);
}

TEST(Planes, BoundaryPointsLieOnTheFaceRim) {
  const auto s = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  const Eigen::Vector3d half(1.5, 1.0, 0.5);
  for (const auto& p : s.planes.planes) {
    ASSERT_FALSE(p.boundary.empty());
    std::size_t on_rim = 0;
    for (std::uint32_t i : p.boundary) {
      // In box coordinates, a rim point is near two of the box's bounding planes.
      const Eigen::Vector3d local = s.spec.pose.axes * (s.pre.points[i] - s.spec.pose.center);
      int near = 0;
      for (int k = 0; k < 3; ++k) near += std::abs(std::abs(local[k]) - half[k]) < 4 * s.pre.resolution;
      on_rim += near >= 2;
    }
    // Voxel centroids are irregular, so a few interior points show a wide gap too.
    EXPECT_GT(static_cast<double>(on_rim), 0.95 * static_cast<double>(p.boundary.size()));
    // And the rim is covered: a face's perimeter holds many boundary points.
    EXPECT_GT(p.boundary.size(), 40u);
  }
}

// The boundary tests split over a pool give what one thread gives: the same planes, labels and
// boundary points in the same order, also where the candidates (here a whole face's points, some
// thousands) make many blocks whose results are joined.
TEST(Planes, ThreadPoolGivesTheSameSegmentation) {
  const auto s = stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  const config::PipelineConfig cfg;
  parallel::ThreadPool pool(3);
  const PlaneSegmentation pooled = segment_planes(s.pre.points, s.pre.resolution, cfg.planes, nullptr, &pool);
  ASSERT_EQ(pooled.planes.size(), s.planes.planes.size());
  EXPECT_EQ(pooled.labels, s.planes.labels);
  for (std::size_t k = 0; k < pooled.planes.size(); ++k) {
    EXPECT_EQ(pooled.planes[k].inliers, s.planes.planes[k].inliers);
    EXPECT_EQ(pooled.planes[k].boundary, s.planes.planes[k].boundary);
  }
  EXPECT_EQ(pooled.lines.size(), s.planes.lines.size());
  const geometry::KdTree tree(s.pre.points);
  const DetectedPlane& face = s.planes.planes.front();
  ASSERT_GT(face.inliers.size(), 1000u);
  const auto alone = find_plane_boundary(tree, s.planes.labels, 0, face.plane, face.inliers, cfg.planes);
  const auto shared = find_plane_boundary(tree, s.planes.labels, 0, face.plane, face.inliers, cfg.planes, &pool);
  EXPECT_EQ(shared, alone);
  EXPECT_GT(alone.size(), 20u);  // the face's rim
  EXPECT_LT(alone.size(), face.inliers.size() / 2);
}

}  // namespace
}  // namespace cloudshape::pipeline
