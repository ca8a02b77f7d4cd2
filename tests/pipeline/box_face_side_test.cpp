// A box face's side (which end of the points along its axis it bounds) comes from where it lies,
// not from the sign of its plane's normal, which segment_planes cannot always settle.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "pipeline/solids.hpp"
#include "stage_fixtures.hpp"

namespace cloudshape::pipeline {
namespace {

std::optional<FittedSolid> box_of(const testing::StagedCloud& s, const PlaneSegmentation& planes,
                                  const config::SolveConfig& cfg) {
  const SolveInput in(s.pre.points, planes, s.keypoints, s.classification, s.pre.resolution, cfg);
  return fit_box(in);
}

// segment_planes turns a face's normal away from the cloud's centroid; where one face holds most
// of the points (a single view of it, a real box's bulging face cut into pieces) that centroid
// lies in the face, and a piece's normal may come out either way. An exact box with one face's
// opposite face left out (unseen: that end is placed by the points' spread) and the face's normal
// turned over, each face in turn: the same box (within rounding: the frame's axes take their signs
// from the faces' normals). Before, the turned face was taken for the unseen one, and the box came
// out about half as deep along it.
TEST(BoxFaceSide, ATurnedFaceNormalGivesTheSameBox) {
  const testing::StagedCloud s = testing::stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  const config::SolveConfig cfg;
  constexpr double kSame = 1e-6;
  int turned_faces = 0;
  for (std::size_t k = 0; k < s.planes.planes.size(); ++k) {
    if (!s.planes.planes[k].is_face) continue;
    PlaneSegmentation seen = s.planes;
    const Eigen::Vector3d normal = seen.planes[k].plane.normal;
    seen.planes.erase(
        std::remove_if(seen.planes.begin(), seen.planes.end(),
                       [&](const DetectedPlane& p) { return p.plane.normal.dot(normal) < -0.99; }),
        seen.planes.end());
    if (seen.planes.size() == s.planes.planes.size()) continue;
    const std::optional<FittedSolid> reference = box_of(s, seen, cfg);
    ASSERT_TRUE(reference.has_value()) << "face " << k;
    PlaneSegmentation turned = seen;
    for (DetectedPlane& p : turned.planes) {
      if (p.plane.normal.dot(normal) < 0.99) continue;
      p.plane.normal = -p.plane.normal;
      p.plane.offset = -p.plane.offset;
    }
    const std::optional<FittedSolid> box = box_of(s, turned, cfg);
    ASSERT_TRUE(box.has_value()) << "face " << k;
    ASSERT_EQ(box->dimensions.size(), reference->dimensions.size());
    for (std::size_t d = 0; d < box->dimensions.size(); ++d)
      EXPECT_NEAR(box->dimensions[d].second, reference->dimensions[d].second, kSame)
          << "face " << k << ", " << box->dimensions[d].first;
    EXPECT_LT((box->center - reference->center).norm(), kSame) << "face " << k;
    ++turned_faces;
  }
  EXPECT_EQ(turned_faces, 6);
}

}  // namespace
}  // namespace cloudshape::pipeline
