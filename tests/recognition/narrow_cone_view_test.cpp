// A narrow cone standing against a wall, seen from above by a depth camera (cloudshape-synth
// scene, exact truth): its own points, base hidden by the table, give the cone and its size.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape {
namespace {

// The narrow cone (radius under 0.3 of the height) of a generated scene, recognised from its own
// points: shape, radius and height within `tolerance`.
void expect_the_narrow_cone(synth::SceneLayout layout, std::uint64_t seed, double tolerance) {
  synth::SceneRecipe recipe;
  recipe.layout = layout;
  recipe.count = 3;
  recipe.seed = seed;
  const synth::SceneCapture capture = synth::capture_scene(recipe, synth::CaptureOptions{});
  for (const synth::SceneObject& object : capture.scene.objects) {
    if (object.solid.kind != synth::ShapeKind::cone) continue;
    const double radius = synth::dimension(object.solid, "radius");
    const double height = synth::dimension(object.solid, "height");
    if (radius / height > 0.3) continue;
    PointList points;
    for (std::size_t i = 0; i < capture.image.points.size(); ++i)
      if (capture.image.labels[i] == object.label && capture.image.points[i].allFinite())
        points.push_back(capture.image.points[i]);
    SCOPED_TRACE("label " + std::to_string(object.label) + ", " + std::to_string(points.size()) + " points");
    const auto result = pipeline::recognize_cloud(points, config::PipelineConfig{}, "narrow cone");
    ASSERT_EQ(result.objects.size(), 1u);
    const auto& cone = result.objects.front();
    ASSERT_EQ(cone.shape, "cone");
    ASSERT_EQ(cone.dimensions.size(), 2u);
    EXPECT_NEAR(cone.dimensions[0].second, radius, tolerance * radius);
    EXPECT_NEAR(cone.dimensions[1].second, height, tolerance * height);
    return;
  }
  FAIL() << "the layout's seed no longer holds a narrow cone";
}

// Wall layout, seed 5: a cone of half-angle 14 deg (radius 41.5 mm, height 166 mm) standing 1.1 m
// from the camera, 2 300 points. Before: the largest flat patch of its side, taken for a base, gave
// a cone 65 m tall (kept, since it explained 70% of the points, so the base-free fit was never
// tried), and the base-free fit's tangent planes met with an eigenvalue ratio of 0.0056, under
// the 0.01 solve.apex_conditioning then took: a leaning cylinder, radius 35 mm. Measured now:
// radius -1.5%, height +2.0%; tolerance 3%.
TEST(NarrowConeView, StandingAgainstAWall) { expect_the_narrow_cone(synth::SceneLayout::wall, 5, 0.03); }

// Row layout, seed 6: a cone of half-angle 16 deg (radius 56 mm, height 198 mm) lying on its
// side, seen over about a third of a turn, 4 000 points: tangent planes meeting with a ratio of
// 0.0025, a cylinder under apex_conditioning 0.004. Measured now: radius +7.1% (the far side
// of the turn is extrapolated), height -3.7%; tolerance 10%.
TEST(NarrowConeView, LyingInARow) { expect_the_narrow_cone(synth::SceneLayout::row, 6, 0.10); }

}  // namespace
}  // namespace cloudshape
