// A narrow cone standing against a wall, seen from above by a depth camera (cloudshape-synth
// scene, exact truth): its own points, base hidden by the table, give the cone and its size.
#include <gtest/gtest.h>

#include <string>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape {
namespace {

// Wall layout, seed 5: a cone of half-angle 14 deg (radius 41.5 mm, height 166 mm) 1.1 m from the
// camera, 2 300 points. Before: the largest flat patch of its side, taken for a base, gave a cone
// 65 m tall (kept, since it explained 70% of the points, so the base-free fit was never tried),
// and the base-free fit's tangent planes met with an eigenvalue ratio of 0.0056, under the 0.01
// solve.apex_conditioning then took: a leaning cylinder, radius 35 mm. Tolerance: 3% (the
// side-only views of ConeParameters.* are within 0.5%; here part of the side is hidden).
TEST(NarrowConeView, ItsOwnPointsGiveTheCone) {
  synth::SceneRecipe recipe;
  recipe.layout = synth::SceneLayout::wall;
  recipe.count = 3;
  recipe.seed = 5;
  const synth::SceneCapture capture = synth::capture_scene(recipe, synth::CaptureOptions{});
  for (const synth::SceneObject& object : capture.scene.objects) {
    if (object.solid.kind != synth::ShapeKind::cone) continue;
    PointList points;
    for (std::size_t i = 0; i < capture.image.points.size(); ++i)
      if (capture.image.labels[i] == object.label && capture.image.points[i].allFinite())
        points.push_back(capture.image.points[i]);
    const double radius = synth::dimension(object.solid, "radius");
    const double height = synth::dimension(object.solid, "height");
    if (radius / height > 0.3) continue;  // the layout's other cone is a wide one
    SCOPED_TRACE("label " + std::to_string(object.label) + ", " + std::to_string(points.size()) + " points");
    const auto result = pipeline::recognize_cloud(points, config::PipelineConfig{}, "narrow cone");
    ASSERT_EQ(result.objects.size(), 1u);
    const auto& cone = result.objects.front();
    ASSERT_EQ(cone.shape, "cone");
    ASSERT_EQ(cone.dimensions.size(), 2u);
    EXPECT_NEAR(cone.dimensions[0].second, radius, 0.03 * radius);
    EXPECT_NEAR(cone.dimensions[1].second, height, 0.03 * height);
    return;
  }
  FAIL() << "the wall layout's seed 5 no longer holds a narrow cone";
}

}  // namespace
}  // namespace cloudshape
