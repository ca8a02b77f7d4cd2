// Synthetic lidar frames as the tests use them: cloudshape-synth's lidar layout, one object,
// 1 cm range noise (`count` objects: the first a sphere, the others drawn from the six); the
// capture with its truth, or only its finite returns.
#pragma once

#include <cstddef>
#include <cstdint>

#include "synth/range_sensor.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape::testing {

// The SphereCalib frame's sensor (SOURCES.md): 16 beams every 2 degrees from -15 to 15, 0.19
// degrees of azimuth, with `range_noise` (1 cm measured there).
inline synth::Lidar spherecalib_lidar(double range_noise = 0.01) {
  synth::Lidar lidar;
  lidar.rings = 16;
  lidar.min_elevation_deg = -15.0;
  lidar.max_elevation_deg = 15.0;
  lidar.azimuth_step_deg = 0.19;
  lidar.range_noise = range_noise;
  return lidar;
}

inline synth::SceneCapture lidar_capture(std::uint64_t seed,
                                         std::size_t rings = synth::CaptureOptions{}.rings,
                                         std::size_t count = 1) {
  synth::SceneRecipe recipe;
  recipe.layout = synth::SceneLayout::lidar;
  recipe.count = count;
  recipe.seed = seed;
  synth::CaptureOptions options;
  options.range_noise = 0.01;
  options.rings = rings;
  return synth::capture_scene(recipe, options);
}

// The returns of lidar_capture(seed, rings), unorganized (no-return pixels left out).
inline PointList lidar_frame(std::uint64_t seed, std::size_t rings) {
  PointList points;
  for (const Point& p : lidar_capture(seed, rings).image.points) {
    if (p.allFinite()) points.push_back(p);
  }
  return points;
}

}  // namespace cloudshape::testing
