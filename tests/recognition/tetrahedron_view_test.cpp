// A tetrahedron seen on two faces that meet at 108 deg (a regular pentagon's corner, so two sides
// of a pentagonal prism as far as their planes go) is never a pentagonal prism: the prism's
// sides are rectangles the prism's height, the tetrahedron's faces triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "new_shapes_support.hpp"
#include "synth/pose.hpp"

namespace cloudshape::newshapes {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(TetrahedronView, TwoFacesAtAPentagonsCornerAreNoPentagonalPrism) {
  for (std::uint64_t seed = 300; seed < 306; ++seed) {
    std::mt19937_64 rng(seed);
    const synth::Pose pose = synth::random_pose(rng, 100.0);
    // The edge A B along local z; C and D 108 deg apart around it: faces A B C and A B D meet
    // there at 108 deg (outward normals 72 deg apart). Heights differ per seed: any tetrahedron.
    const double half = std::uniform_real_distribution<double>(25.0, 40.0)(rng);
    const double reach = std::uniform_real_distribution<double>(40.0, 55.0)(rng);
    const double a = 108.0 * kPi / 180.0;
    const std::array<Eigen::Vector3d, 4> local = {
        Eigen::Vector3d(0, 0, -half), Eigen::Vector3d(0, 0, half), Eigen::Vector3d(reach, 0, 0.3 * half),
        Eigen::Vector3d(reach * std::cos(a), reach * std::sin(a), -0.2 * half)};
    std::array<Eigen::Vector3d, 4> corners;
    for (int k = 0; k < 4; ++k) corners[k] = pose.to_world(local[k]);
    const synth::SolidMesh mesh = synth::tetrahedron_mesh(corners);
    // Looking at the shared edge from outside, between the two faces' outward normals.
    const Eigen::Vector3d out_local = -Eigen::Vector3d(1.0 + std::cos(a), std::sin(a), 0.0).normalized();
    const Eigen::Vector3d camera = pose.to_world(3.0 * mesh.size * out_local);
    const pipeline::ObjectResult o = recognise_one(sample_view(mesh, 8000, 0.005, camera, seed + 50));
    EXPECT_NE(o.shape, "pentagonal_prism") << "seed " << seed;
  }
}

}  // namespace
}  // namespace cloudshape::newshapes
