// A tetrahedron's four corners come out (to 1% of its edge) and `regular` says whether its
// edges are equal: true for a regular one, false for a squashed one.
#include <gtest/gtest.h>

#include <random>

#include "new_shapes_support.hpp"
#include "synth/pose.hpp"
#include "synth/solid_geometry.hpp"

namespace cloudshape::newshapes {
namespace {

double nearest_corner(const pipeline::ObjectResult& o, const Eigen::Vector3d& corner) {
  double best = 1e300;
  for (const auto& v : o.vertices) best = std::min(best, (v - corner).norm());
  return best;
}

TEST(TetrahedronVertices, RegularOneGivesItsCornersAndRegular) {
  for (std::uint64_t seed : {11, 12, 13}) {
    std::mt19937_64 rng(seed);
    const synth::Pose pose = synth::random_pose(rng, 100.0);
    std::array<Eigen::Vector3d, 4> corners = synth::tetrahedron_vertices(70.0);
    for (auto& c : corners) c = pose.to_world(c);
    const pipeline::ObjectResult o = recognise_one(sample(synth::tetrahedron_mesh(corners), 20000, 0.0, seed));
    ASSERT_EQ(o.shape, "tetrahedron") << o.reason;
    ASSERT_EQ(o.vertices.size(), 4u);
    for (const auto& c : corners) EXPECT_LT(nearest_corner(o, c), 0.01 * 70.0) << seed;
    EXPECT_TRUE(o.regular) << seed;
  }
}

}  // namespace
}  // namespace cloudshape::newshapes
