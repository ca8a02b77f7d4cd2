// Shared by the scene tests: small, fast captures and independent checks of where a point lies
// (the analytic oracle of surface_oracle.hpp, not the ray caster under test).
#pragma once

#include <cmath>

#include "surface_oracle.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape::synth::testing {

inline CaptureOptions small_camera() {
  CaptureOptions options;
  options.width = 160;
  options.height = 120;
  return options;
}

inline SceneCapture capture(SceneLayout layout, std::uint64_t seed, double scale = 1.0,
                            CaptureOptions options = small_camera(), std::size_t count = 3,
                            int walls = -1) {
  SceneRecipe recipe;
  recipe.layout = layout;
  recipe.seed = seed;
  recipe.scale = scale;
  recipe.count = count;
  recipe.walls = walls;
  if (layout == SceneLayout::lidar) options.azimuth_step_deg = 0.5;
  return capture_scene(recipe, options);
}

// Signed distance of p from the rectangle's plane, and whether its foot lies on the rectangle.
inline double plane_distance(const SceneRectangle& r, const Eigen::Vector3d& p) {
  return r.normal().dot(p - r.center);
}
inline bool within(const SceneRectangle& r, const Eigen::Vector3d& p, double tolerance) {
  const Eigen::Vector3d d = p - r.center;
  return std::abs(d.dot(r.u)) <= r.half_u + tolerance &&
         std::abs(d.dot(r.v)) <= r.half_v + tolerance;
}

inline const SceneObject* object_with(const Scene& scene, std::uint32_t label) {
  for (const auto& o : scene.objects)
    if (o.label == label) return &o;
  return nullptr;
}
inline const SceneRectangle* structure_with(const Scene& scene, std::uint32_t label) {
  for (const auto& r : scene.structure)
    if (r.label == label) return &r;
  return nullptr;
}

}  // namespace cloudshape::synth::testing
