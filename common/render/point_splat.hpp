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

// What the drawn points leave in front: per pixel of the clip, the nearest point's depth along
// the camera's forward axis (infinity where no point was drawn).
struct DepthBuffer {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  std::vector<float> depth;
  double near = 0.0, far = 0.0;  // the points' 2nd and 98th percentile of depth

  float at(int x, int y) const;  // infinity outside the clip
};

// Per point of the recognised cloud, the index of the object it went into, or -1.
std::vector<int> object_of_points(const pipeline::RecognitionResult& result, std::size_t points);

// Draws the points that `view` puts inside `clip`. Squares are 1 to 6 pixels wide, as wide as
// the points' typical spacing, so that a surface reads as a surface.
DepthBuffer splat_points(const View& view, const PixelRect& clip, const PointList& points,
                         const std::vector<int>& object_of, PixelBuffer out);

}  // namespace cloudshape::render
