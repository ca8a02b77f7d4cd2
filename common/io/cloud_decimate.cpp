#include "io/cloud_decimate.hpp"

#include <cstdint>

namespace cloudshape::io {

CloudFile decimated(const CloudFile& cloud, std::size_t step) {
  CloudFile out;
  out.format = cloud.format;
  const std::size_t width = cloud.grid.width;
  out.grid.width = (width + step - 1) / step;
  out.grid.height = (cloud.grid.height + step - 1) / step;
  const bool labelled = cloud.labels.size() == cloud.points.size();
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const std::size_t row = cloud.grid.pixel[i] / width, column = cloud.grid.pixel[i] % width;
    if (row % step != 0 || column % step != 0) continue;
    out.points.push_back(cloud.points[i]);
    if (labelled) out.labels.push_back(cloud.labels[i]);
    out.grid.pixel.push_back(
        static_cast<std::uint32_t>(row / step * out.grid.width + column / step));
  }
  return out;
}

}  // namespace cloudshape::io
