// Checks a raw cloud's organized layout against its points and the input limits, naming the
// first problem found: one error result for the cloud instead of an image indexed out of range.
#include "dds/raw_cloud_layout.hpp"

#include <cstdint>
#include <string>

namespace cloudshape::dds {
namespace {

std::string grid_text(std::uint64_t width, std::uint64_t height) {
  return std::to_string(width) + " x " + std::to_string(height);
}

}  // namespace

GridLayout raw_cloud_layout(const msg::RawCloud& cloud, std::size_t points, const config::InputConfig& limits) {
  const std::vector<std::uint32_t>& pixel = cloud.pixel();
  const std::uint64_t width = cloud.width(), height = cloud.height();
  if (pixel.empty() && height <= 1) return {};
  if (height <= 1) {
    throw RawCloudError("pixel holds " + std::to_string(pixel.size()) + " indices but height is " +
                        std::to_string(height) + " (only an organized cloud, height > 1, has pixels)");
  }
  if (width == 0) throw RawCloudError("organized cloud of height " + std::to_string(height) + " with width 0");
  // Two 32-bit factors cannot overflow 64 bits; what can overflow is the 32-bit pixel index.
  const std::uint64_t cells = width * height;
  if (cells > std::uint64_t{UINT32_MAX} + 1) {
    throw RawCloudError("grid " + grid_text(width, height) + " = " + std::to_string(cells) +
                        " pixels, more than 32-bit pixel indices address");
  }
  if (cells > static_cast<std::uint64_t>(limits.max_points)) {
    throw RawCloudError("grid " + grid_text(width, height) + " = " + std::to_string(cells) +
                        " pixels, more than input.max_points " + std::to_string(limits.max_points));
  }
  if (pixel.size() != points) {
    throw RawCloudError("pixel holds " + std::to_string(pixel.size()) + " indices for " + std::to_string(points) +
                        " points (an organized cloud has one per point)");
  }
  for (std::size_t i = 0; i < pixel.size(); ++i) {
    if (pixel[i] >= cells) {
      throw RawCloudError("pixel[" + std::to_string(i) + "] = " + std::to_string(pixel[i]) + " is outside the " +
                          grid_text(width, height) + " grid");
    }
    if (i > 0 && pixel[i] <= pixel[i - 1]) {
      throw RawCloudError("pixel[" + std::to_string(i) + "] = " + std::to_string(pixel[i]) + " does not follow pixel[" +
                          std::to_string(i - 1) + "] = " + std::to_string(pixel[i - 1]) +
                          " (pixels must be strictly increasing)");
    }
  }
  GridLayout grid;
  grid.width = static_cast<std::size_t>(width);
  grid.height = static_cast<std::size_t>(height);
  grid.pixel = pixel;
  return grid;
}

}  // namespace cloudshape::dds
