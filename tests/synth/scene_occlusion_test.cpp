// Occlusion by construction: a box straight in front of a sphere, on the camera's axis. Where the
// box covers the sphere only the box is seen; elsewhere the sphere's depth is the closed-form
// ray-sphere entry, and the sphere loses exactly the pixels the box covers.
#include <gtest/gtest.h>

#include <random>

#include "scene_test_support.hpp"

namespace cloudshape::synth {
namespace {

// box_first: the box comes first in the scene's list, so no order of testing hides a wrong answer.
Scene sphere_behind_box(bool with_box, bool box_first = false) {
  Scene scene;
  SceneObject sphere{make_solid(ShapeKind::sphere, {0.5}), 30};
  sphere.solid.pose.center = {0.0, 0.0, 3.0};
  scene.objects.push_back(sphere);
  if (with_box) {
    // Covers the sphere's left half and more as seen from the origin.
    SceneObject box{make_solid(ShapeKind::box, {0.4, 0.6, 0.1}), 20};
    box.solid.pose.center = {-0.15, 0.0, 1.5};
    scene.objects.insert(box_first ? scene.objects.begin() : scene.objects.end(), box);
  }
  return scene;
}

RangeImage look_along_z(const Scene& scene) {
  DepthCamera camera;
  camera.width = 120;
  camera.height = 90;
  SensorPose pose;  // at the origin, axes = world axes: looking along +z
  std::mt19937_64 rng(1);
  return render(scene, camera, pose, rng);
}

class SceneOcclusion : public ::testing::TestWithParam<bool> {};

TEST_P(SceneOcclusion, TheBoxHidesThePartOfTheSphereBehindIt) {
  const RangeImage alone = look_along_z(sphere_behind_box(false));
  const RangeImage both = look_along_z(sphere_behind_box(true, GetParam()));
  DepthCamera camera;
  camera.width = 120;
  camera.height = 90;
  std::size_t hidden = 0, sphere_seen = 0, box_seen = 0;
  for (std::size_t row = 0; row < 90; ++row) {
    for (std::size_t column = 0; column < 120; ++column) {
      const std::size_t i = row * 120 + column;
      const Eigen::Vector3d d = camera.pixel_ray(column, row).normalized();
      // The box (0.4 along x, 0.6 along y, 0.1 deep) faces the camera with the plane z = 1.45,
      // x in [-0.35, 0.05], y in [-0.3, 0.3]; the sphere's entry along d in closed form.
      const Eigen::Vector3d on_front = d * (1.45 / d.z());
      const bool box_in_front =
          std::abs(on_front.x() + 0.15) <= 0.2 && std::abs(on_front.y()) <= 0.3;
      const double b = d.dot(Eigen::Vector3d(0, 0, 3));
      const double disc = b * b - (9.0 - 0.25);
      const bool on_sphere = disc > 0.0;
      if (box_in_front) {
        EXPECT_EQ(both.labels[i], 20u) << row << "," << column;
        EXPECT_NEAR(both.points[i].z(), 1.45, 1e-9);
        box_seen += 1;
        if (on_sphere) {
          EXPECT_EQ(alone.labels[i], 30u);
          hidden += 1;
        }
      } else if (on_sphere && disc > 1e-6) {
        ASSERT_EQ(both.labels[i], 30u) << row << "," << column;
        EXPECT_NEAR((both.points[i] - (b - std::sqrt(disc)) * d).norm(), 0.0, 1e-9);
        sphere_seen += 1;
      }
    }
  }
  // The construction really occludes: a good share of the sphere is behind the box.
  EXPECT_GT(hidden, 200u);
  EXPECT_GT(sphere_seen, 200u);
  std::size_t sphere_alone = 0, sphere_both = 0;
  for (std::size_t i = 0; i < alone.labels.size(); ++i) {
    sphere_alone += alone.labels[i] == 30 ? 1 : 0;
    sphere_both += both.labels[i] == 30 ? 1 : 0;
  }
  EXPECT_EQ(sphere_alone - sphere_both, hidden);
  EXPECT_GT(box_seen, hidden);
}

// A row seen along its line: nearer objects hide parts of farther ones, in most scenes.
TEST(SceneOcclusion, RowsSeenAlongTheirLineHaveObjectsHidingEachOther) {
  std::size_t scenes_with_occlusion = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    SceneRecipe recipe;
    recipe.layout = SceneLayout::row;
    recipe.count = 4;
    recipe.seed = seed;
    const GeneratedScene g = make_scene(recipe);
    DepthCamera camera;
    camera.width = 160;
    camera.height = 120;
    std::mt19937_64 rng(1);
    const RangeImage all = render(g.scene, camera, g.sensor, rng);
    std::size_t hidden = 0;
    for (const auto& object : g.scene.objects) {
      Scene alone;
      alone.objects.push_back(object);
      const RangeImage one = render(alone, camera, g.sensor, rng);
      for (std::size_t i = 0; i < one.labels.size(); ++i)
        hidden +=
            one.labels[i] == object.label && all.labels[i] >= 20 && all.labels[i] != object.label
                ? 1
                : 0;
    }
    scenes_with_occlusion += hidden > 10 ? 1 : 0;
  }
  EXPECT_GE(scenes_with_occlusion, 4u);
}

INSTANTIATE_TEST_SUITE_P(ObjectOrder, SceneOcclusion, ::testing::Bool(), [](const auto& info) {
  return info.param ? "box_first" : "sphere_first";
});

}  // namespace
}  // namespace cloudshape::synth
