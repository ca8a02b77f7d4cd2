// Positive tetrahedron recognition against ground truth: noisy, with outliers, one view.
// Edge, centroid and orientation (the four vertex directions) within stated tolerances.
#include <gtest/gtest.h>

#include "positive_support.hpp"
#include "synth/solid_geometry.hpp"

namespace cloudshape::positive {
namespace {

const std::vector<std::uint64_t> kSeeds = {61, 62, 63, 64, 65, 66};

synth::SolidSpec random_tetrahedron(std::mt19937_64& rng) {
  const double edge = random_size(rng);
  return synth::make_solid(synth::ShapeKind::tetrahedron, {edge}, random_pose(rng, edge));
}

// Outward normal of the face opposite vertex i, in world coordinates.
Eigen::Vector3d face_normal(const synth::SolidSpec& truth, int i) {
  return truth.pose.axes.transpose() * -synth::tetrahedron_vertices(1.0)[i].normalized();
}

// Worst over 46 seeds (40 others and these 6) when these were set (edge / centre share of the edge
// / vertex directions): noise 0.75% / 0.69% / 1.76 deg, outliers 0.87% / 0.75% / 1.53 deg, single
// views 0.79% / 0.29% / 0.02 deg, noisy single view 0.56% / 0.28% / 0.36 deg. Each tolerance is 2-3
// times that.
constexpr Tolerance kNoisy{0.02, 0.02, 3.0};
constexpr Tolerance kOutliers{0.02, 0.02, 3.0};
constexpr Tolerance kSingleView{0.02, 0.01, 0.5};
constexpr Tolerance kSingleViewNoisy{0.02, 0.01, 1.0};

TEST(TetrahedronParameters, Noisy) {
  check_seeds(
      kSeeds, random_tetrahedron, [](const auto&, auto&) { return noisy(); }, false, kNoisy);
}

TEST(TetrahedronParameters, NoisyWithOutliers) {
  check_seeds(
      kSeeds, random_tetrahedron, [](const auto&, auto&) { return noisy_with_outliers(); }, false,
      kOutliers);
}

// Between two face normals: exactly those two faces, which hold all four vertices.
TEST(TetrahedronParameters, SingleViewOfTwoFaces) {
  check_seeds(
      kSeeds, random_tetrahedron,
      [](const synth::SolidSpec& truth, auto&) {
        return seen_from(face_normal(truth, 0) + face_normal(truth, 1));
      },
      true, kSingleView);
}

// Opposite a face: the other three.
TEST(TetrahedronParameters, SingleViewOfThreeFaces) {
  check_seeds(
      kSeeds, random_tetrahedron,
      [](const synth::SolidSpec& truth, auto&) { return seen_from(-face_normal(truth, 3)); }, true,
      kSingleView);
}

TEST(TetrahedronParameters, SingleViewOfThreeFacesNoisy) {
  check_seeds(
      kSeeds, random_tetrahedron,
      [](const synth::SolidSpec& truth, auto&) { return seen_from(-face_normal(truth, 3), 0.005); },
      true, kSingleViewNoisy);
}

}  // namespace
}  // namespace cloudshape::positive
