// A single view of any tetrahedron: two faces seen give all four corners (the edge they share
// and each one's third corner), and two faces meeting at 108 deg (a regular pentagon's corner, so
// two sides of a pentagonal prism as far as their planes go) are never a pentagonal prism: the
// prism's sides are rectangles the prism's height, the tetrahedron's faces triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "new_shapes_support.hpp"
#include "synth/pose.hpp"

namespace cloudshape::newshapes {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A tetrahedron with the edge A B along local z and C, D `opening` apart around it (faces A B C
// and A B D meet there at that angle), heights and reach drawn per seed, and what a camera sees
// looking at A B from outside, between the two faces' outward normals.
struct TwoFaceView {
  std::array<Eigen::Vector3d, 4> corners;
  synth::SolidMesh mesh;
  pipeline::ObjectResult result;
};

TwoFaceView two_face_view(std::uint64_t seed, std::optional<double> opening_degrees) {
  std::mt19937_64 rng(seed);
  const synth::Pose pose = synth::random_pose(rng, 100.0);
  const double half = std::uniform_real_distribution<double>(25.0, 40.0)(rng);
  const double reach = std::uniform_real_distribution<double>(40.0, 55.0)(rng);
  const double a =
      opening_degrees.value_or(std::uniform_real_distribution<double>(85.0, 145.0)(rng)) * kPi /
      180.0;
  const std::array<Eigen::Vector3d, 4> local = {
      Eigen::Vector3d(0, 0, -half), Eigen::Vector3d(0, 0, half),
      Eigen::Vector3d(reach, 0, 0.3 * half),
      Eigen::Vector3d(reach * std::cos(a), reach * std::sin(a), -0.2 * half)};
  TwoFaceView out;
  for (int k = 0; k < 4; ++k) out.corners[k] = pose.to_world(local[k]);
  out.mesh = synth::tetrahedron_mesh(out.corners);
  const Eigen::Vector3d out_local =
      -Eigen::Vector3d(1.0 + std::cos(a), std::sin(a), 0.0).normalized();
  const Eigen::Vector3d camera = pose.to_world(3.0 * out.mesh.size * out_local);
  out.result = recognise_one(sample_view(out.mesh, 8000, 0.005, camera, seed + 50));
  return out;
}

TEST(TetrahedronView, TwoFacesAtAPentagonsCornerAreNoPentagonalPrism) {
  for (std::uint64_t seed = 300; seed < 306; ++seed)
    EXPECT_NE(two_face_view(seed, 108.0).result.shape, "pentagonal_prism") << "seed " << seed;
}

// Two faces of an irregular tetrahedron (opening 85-145 deg: no regular one's), seen from outside
// their shared edge: a tetrahedron, each corner within 3% of the size of a true one, the mean
// edge within 3%.
TEST(TetrahedronView, TwoFacesOfAnyTetrahedronGiveItsCorners) {
  for (std::uint64_t seed = 310; seed < 318; ++seed) {
    const TwoFaceView v = two_face_view(seed, std::nullopt);
    const pipeline::ObjectResult& o = v.result;
    double edge = 0.0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edge += (v.corners[i] - v.corners[j]).norm() / 6.0;
    SCOPED_TRACE("seed " + std::to_string(seed));
    ASSERT_EQ(o.shape, "tetrahedron");
    EXPECT_TRUE(o.partial);
    EXPECT_NEAR(dimension(o, "edge"), edge, 0.03 * edge);
    ASSERT_EQ(o.vertices.size(), 4u);
    for (const Eigen::Vector3d& c : v.corners) {
      double nearest = 1e300;
      for (const Eigen::Vector3d& p : o.vertices) nearest = std::min(nearest, (p - c).norm());
      EXPECT_LT(nearest, 0.03 * v.mesh.size);
    }
  }
}

// A box seen on two faces is no tetrahedron: each face is a rectangle, twice the triangle of the
// shared edge and its farthest point.
TEST(TetrahedronView, TwoFacesOfABoxAreNoTetrahedron) {
  for (std::uint64_t seed = 320; seed < 324; ++seed) {
    std::mt19937_64 rng(seed);
    const synth::Pose pose = synth::random_pose(rng, 100.0);
    const geometry::Polygon2 rectangle{{-40.0, -25.0}, {40.0, -25.0}, {40.0, 25.0}, {-40.0, 25.0}};
    const synth::SolidMesh mesh = synth::prism_mesh(rectangle, 60.0, pose);
    // Along the extrusion axis (local x) hardly at all: the two long sides facing the camera.
    const Eigen::Vector3d camera =
        pose.to_world(3.0 * mesh.size * Eigen::Vector3d(0.02, 1.0, 1.0).normalized());
    const pipeline::ObjectResult o =
        recognise_one(sample_view(mesh, 8000, 0.005, camera, seed + 50));
    EXPECT_EQ(o.shape, "box") << "seed " << seed;
  }
}

}  // namespace
}  // namespace cloudshape::newshapes
