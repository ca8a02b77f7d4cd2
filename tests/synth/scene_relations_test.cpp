// What the layouts promise, checked on the generated solids with the analytic oracle: objects rest
// on the plane, a touching pair meets with gap 0, a stacked box rests on the one below, objects
// against a wall touch it, and no two solids overlap.
#include <gtest/gtest.h>

#include <random>

#include "scene_test_support.hpp"
#include "synth/sample_solid.hpp"
#include "synth/scene_placement.hpp"

namespace cloudshape::synth {
namespace {

const Eigen::Vector3d kX = Eigen::Vector3d::UnitX(), kY = Eigen::Vector3d::UnitY(),
                      kZ = Eigen::Vector3d::UnitZ();

GeneratedScene generate(SceneLayout layout, std::uint64_t seed, std::size_t count, int walls = -1) {
  SceneRecipe recipe;
  recipe.layout = layout;
  recipe.seed = seed;
  recipe.count = count;
  recipe.walls = walls;
  return make_scene(recipe);
}

// Deepest any sampled surface point of `a` goes into `b` (>= 0 when they do not overlap).
double deepest_penetration(const SolidSpec& a, const SolidSpec& b) {
  std::mt19937_64 rng(7);
  double worst = 1e300;
  for (const auto& p : sample_solid_surface(a, 4000, rng))
    worst = std::min(worst, testing::surface_residual(b, p));
  return worst;
}

void expect_no_overlap(const GeneratedScene& g) {
  const auto& objects = g.scene.objects;
  for (std::size_t i = 0; i < objects.size(); ++i)
    for (std::size_t j = 0; j < objects.size(); ++j)
      if (i != j) {
        EXPECT_GE(deepest_penetration(objects[i].solid, objects[j].solid), -1e-9)
            << i << " in " << j;
      }
}

constexpr double kTol = 1e-12;  // of a scene whose unit is 1

TEST(SceneRelations, TouchingNeighboursMeetWithGapZero) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const GeneratedScene g = generate(SceneLayout::touching, seed, 4);
    ASSERT_EQ(g.touching.size(), 3u);
    for (const auto& [a, b] : g.touching) {
      const SolidSpec& left = g.scene.objects[a].solid;
      const SolidSpec& right = g.scene.objects[b].solid;
      const double contact = highest(left, kX);
      EXPECT_NEAR(lowest(right, kX), contact, kTol) << "seed " << seed;
      // A point of the contact (the neighbours share the plane y = 0 through their centres and
      // both reach the table) lies on both surfaces: they touch there.
      const double z = 0.5 * std::min(highest(left, kZ), highest(right, kZ));
      const Eigen::Vector3d p(contact, 0.0, z);
      EXPECT_NEAR(testing::surface_residual(left, p), 0.0, kTol) << "seed " << seed;
      EXPECT_NEAR(testing::surface_residual(right, p), 0.0, kTol) << "seed " << seed;
    }
    expect_no_overlap(g);
  }
}

TEST(SceneRelations, StackedBoxRestsOnTheLowerOne) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const GeneratedScene g = generate(SceneLayout::stacked, seed, 4);
    ASSERT_EQ(g.stacked.size(), 2u);
    for (const auto& [up, down] : g.stacked) {
      const SolidSpec& upper = g.scene.objects[up].solid;
      const SolidSpec& lower = g.scene.objects[down].solid;
      ASSERT_EQ(upper.kind, ShapeKind::box);
      ASSERT_EQ(lower.kind, ShapeKind::box);
      const double top = highest(lower, kZ);
      EXPECT_NEAR(lowest(upper, kZ), top, kTol) << "seed " << seed;
      // Below the upper box's centre of mass: a point on both surfaces, inside the lower top face.
      const Eigen::Vector3d under(upper.pose.center.x(), upper.pose.center.y(), top);
      EXPECT_NEAR(testing::surface_residual(upper, under), 0.0, kTol) << "seed " << seed;
      EXPECT_NEAR(testing::surface_residual(lower, under), 0.0, kTol) << "seed " << seed;
      const Eigen::Vector3d q = testing::to_local(lower.pose, under);
      for (int k = 0; k < 3; ++k)
        if (std::abs(lower.pose.axes(k, 2)) < 0.5) {
          EXPECT_LT(std::abs(q[k]), 0.25 * lower.dimensions[k].second);
        }
    }
    // The bottom box and the objects beside the stack stand on the table.
    EXPECT_NEAR(lowest(g.scene.objects[0].solid, kZ), 0.0, kTol);
    EXPECT_NEAR(lowest(g.scene.objects[3].solid, kZ), 0.0, kTol);
    expect_no_overlap(g);
  }
}

TEST(SceneRelations, ObjectsAgainstAWallTouchItAndRestOnThePlane) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const GeneratedScene g = generate(SceneLayout::wall, seed, 3, 2);
    ASSERT_EQ(g.against_wall.size(), 4u);  // all three on the back wall, the last also on the side
    for (const auto& [index, label] : g.against_wall) {
      const SolidSpec& s = g.scene.objects[index].solid;
      const SceneRectangle* wall = testing::structure_with(g.scene, label);
      ASSERT_NE(wall, nullptr);
      // The walls stand at +y (back) and +x (side): the solid reaches the wall's plane exactly.
      const Eigen::Vector3d towards = wall->normal().cwiseAbs();
      EXPECT_NEAR(highest(s, towards), towards.dot(wall->center), kTol)
          << "seed " << seed << " wall " << label;
    }
    for (const auto& o : g.scene.objects) EXPECT_NEAR(lowest(o.solid, kZ), 0.0, kTol);
    expect_no_overlap(g);
  }
}

TEST(SceneRelations, ThePlaneIsLargerThanTheObjectsByAMargin) {
  for (const auto layout : {SceneLayout::row, SceneLayout::random, SceneLayout::touching}) {
    const GeneratedScene g = generate(layout, 9, 3);
    const SceneRectangle& plane = g.scene.structure.at(0);
    ASSERT_EQ(plane.label, 1u);
    for (const auto& o : g.scene.objects) {
      EXPECT_NEAR(lowest(o.solid, kZ), 0.0, kTol);
      EXPECT_LT(highest(o.solid, kX), plane.center.x() + plane.half_u - 0.05);
      EXPECT_GT(lowest(o.solid, kX), plane.center.x() - plane.half_u + 0.05);
      EXPECT_LT(highest(o.solid, kY), plane.center.y() + plane.half_v - 0.05);
      EXPECT_GT(lowest(o.solid, kY), plane.center.y() - plane.half_v + 0.05);
    }
    expect_no_overlap(g);
  }
}

TEST(SceneRelations, CountAndScaleAreChecked) {
  EXPECT_THROW(generate(SceneLayout::touching, 1, 1), std::invalid_argument);
  EXPECT_THROW(generate(SceneLayout::row, 1, 6), std::invalid_argument);
  EXPECT_THROW(generate(SceneLayout::wall, 1, 3, 0), std::invalid_argument);
  SceneRecipe bad;
  bad.scale = 0.0;
  EXPECT_THROW(make_scene(bad), std::invalid_argument);
}

}  // namespace
}  // namespace cloudshape::synth
