// A generated scene as a depth camera's organized frame: its finite points, their pixels and
// their truth labels, as the segmentation tests read it.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape::segment {

struct CapturedScene {
  PointList points;
  GridLayout grid;
  std::vector<std::uint32_t> labels;          // per point: 1-9 structure, 20+ an object
  std::map<std::uint32_t, std::size_t> size;  // points per label
};

// The finite pixels of a rendered frame, with their pixels and labels.
inline CapturedScene captured_points(const synth::RangeImage& image) {
  CapturedScene out;
  out.grid = GridLayout{image.width, image.height, {}};
  for (std::size_t i = 0; i < image.points.size(); ++i) {
    if (!image.points[i].allFinite()) continue;
    out.points.push_back(image.points[i]);
    out.grid.pixel.push_back(static_cast<std::uint32_t>(i));
    out.labels.push_back(image.labels[i]);
    ++out.size[image.labels[i]];
  }
  return out;
}

inline CapturedScene capture_points(const synth::SceneRecipe& recipe,
                                    const synth::CaptureOptions& options) {
  return captured_points(synth::capture_scene(recipe, options).image);
}

}  // namespace cloudshape::segment
