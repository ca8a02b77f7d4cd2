#include "segment/detail/depth_noise.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/robust_spread.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

double depth_noise_ratio(const DepthImage& image, double depth_jump, std::size_t row_step) {
  std::vector<double> ratios;
  const std::size_t w = image.width;
  for (std::size_t y = 0; y < image.height; y += std::max<std::size_t>(1, row_step)) {
    for (std::size_t x = 1; x + 1 < w; ++x) {
      const std::size_t i = y * w + x;
      const double left = image.range[i - 1], centre = image.range[i], right = image.range[i + 1];
      if (!same_surface(centre, left, depth_jump) || !same_surface(centre, right, depth_jump))
        continue;
      const Point& a = image.points[static_cast<std::size_t>(image.point[i - 1])];
      const Point& b = image.points[static_cast<std::size_t>(image.point[i + 1])];
      const double pitch = 0.5 * centre * (a / left - b / right).norm();
      if (!(pitch > 0.0)) continue;
      ratios.push_back(std::abs(centre - 0.5 * (left + right)) / pitch);
    }
  }
  if (ratios.size() < 3) return 0.0;
  return geometry::robust_deviation(std::move(ratios)) / std::sqrt(1.5);
}

std::size_t normal_window_step(double noise_ratio, std::size_t stride, std::int64_t radius,
                               double max_tilt_degrees, std::size_t extent) {
  const double r = static_cast<double>(std::max<std::int64_t>(1, radius));
  const double tilt = std::tan(std::clamp(max_tilt_degrees, 0.0, 89.0) * kPi / 180.0);
  stride = std::max<std::size_t>(1, stride);
  if (!(noise_ratio > 0.0) || !(tilt > 0.0)) return stride;
  // Sum over the (2r + 1)^2 samples of the squared offset along one axis, in steps.
  const double offsets = (2.0 * r + 1.0) * r * (r + 1.0) * (2.0 * r + 1.0) / 3.0;
  const double needed = std::ceil(noise_ratio / (std::sqrt(offsets) * tilt));
  const double widest = std::max(1.0, std::floor(static_cast<double>(extent) / (2.0 * r)));
  return std::max(stride, static_cast<std::size_t>(std::min(needed, widest)));
}

}  // namespace cloudshape::segment::detail
