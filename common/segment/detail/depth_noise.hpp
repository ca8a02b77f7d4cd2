// How noisy an organized cloud's depth is next to its pixel pitch, and how far apart a node's
// normal window must sample its pixels for that noise to tilt the normal by no more than a bound.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::segment::detail {

// The depth image as the normal windows read it: per pixel its point (-1: none) and that point's
// range (NaN: none), row-major, `width` x `height`.
struct DepthImage {
  const PointList& points;
  const std::vector<std::int32_t>& point;
  const std::vector<double>& range;
  std::size_t width, height;
};

// The range noise of independent pixels, as a share of the pixel pitch (the distance between
// neighbouring pixels' rays at that range): each pixel's range against the mean of its left and
// right neighbours' where all three lie on one surface (`depth_jump`), over half the distance
// between the neighbours' rays there, the median of that as a Gaussian's deviation (each
// difference holds 1.5 pixels' noise). Every `row_step`-th row is read. A sensor whose depth is
// matched over windows of pixels (a Kinect) varies smoothly from pixel to pixel: about 0.001; a
// depth image with independent noise per pixel, about the noise over the pitch. 0 when fewer
// than 3 pixels have both neighbours.
double depth_noise_ratio(const DepthImage& image, double depth_jump, std::size_t row_step);

// The pixels between a normal window's samples (its 2 radius + 1 samples a side): `stride` (the
// node cells') unless independent noise of `noise_ratio` pitches would tilt the window's plane by
// more than `max_tilt_degrees` (one deviation, along either axis): then wide enough that it does
// not, the least-squares slope's deviation being the noise over the step times the square root of
// the window's summed squared sample offsets; at most what keeps the window inside `extent` pixels.
std::size_t normal_window_step(double noise_ratio, std::size_t stride, std::int64_t radius,
                               double max_tilt_degrees, std::size_t extent);

}  // namespace cloudshape::segment::detail
