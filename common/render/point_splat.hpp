// Points drawn straight into a 32-bit pixel buffer through a depth buffer, so that near points
// hide far ones: each a small square in its object's colour, darker the farther it is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "pipeline/result.hpp"
#include "render/view.hpp"

namespace cloudshape::render {

// Cairo's CAIRO_FORMAT_RGB24 / ARGB32 layout: one 0xAARRGGBB word per pixel, rows `stride`
// words apart.
struct PixelBuffer {
  std::uint32_t* pixels = nullptr;
  int stride = 0;
  int width = 0;
  int height = 0;
};

// Per point of the recognised cloud, the index of the object it went into, or -1.
std::vector<int> object_of_points(const pipeline::RecognitionResult& result, std::size_t points);

// Draws the points that `view` puts inside `clip`. Squares are 1 to 6 pixels wide, as wide as
// the points' typical spacing, so that a surface reads as a surface.
void splat_points(const View& view, const PixelRect& clip, const PointList& points,
                  const std::vector<int>& object_of, PixelBuffer out);

}  // namespace cloudshape::render
