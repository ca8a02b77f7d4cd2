// Builds a sensor_msgs/PointCloud2 (plain value) from points, in a chosen byte layout.
// Missing pixels of an organized grid become NaN points, as a depth camera sends them.
#include "io/pointcloud2_encode.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace cloudshape::io {
namespace {

// A packed 0x00RRGGBB colour as the FLOAT32 that drivers put in "rgb".
constexpr std::uint32_t kGrey = 0x808080;

template <typename T>
void store(std::uint8_t* p, T value, bool big_endian) {
  std::memcpy(p, &value, sizeof(T));
  if (big_endian) std::reverse(p, p + sizeof(T));
}

}  // namespace

PointCloud2Layout float64_layout() {
  PointCloud2Layout layout;
  layout.coordinate = PointFieldType::float64;
  layout.offsets = {0, 8, 16};
  layout.rgb_offset = 24;
  layout.point_step = 32;
  return layout;
}

PointCloud2 encode_pointcloud2(const PointList& points, const GridLayout& grid,
                               const PointCloud2Layout& layout, const RosHeader& header) {
  const bool f64 = layout.coordinate == PointFieldType::float64;
  if (!f64 && layout.coordinate != PointFieldType::float32) {
    throw std::invalid_argument("PointCloud2 coordinates must be FLOAT32 or FLOAT64");
  }
  const std::uint32_t size = f64 ? 8 : 4;
  for (std::uint32_t offset : layout.offsets) {
    if (offset + size > layout.point_step) throw std::invalid_argument("a coordinate does not fit in point_step");
  }
  if (layout.rgb && layout.rgb_offset + 4 > layout.point_step) {
    throw std::invalid_argument("rgb does not fit in point_step");
  }

  PointCloud2 cloud;
  cloud.header = header;
  const bool organized = grid.organized();
  cloud.height = organized ? static_cast<std::uint32_t>(grid.height) : 1;
  cloud.width = organized ? static_cast<std::uint32_t>(grid.width) : static_cast<std::uint32_t>(points.size());
  const char* names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    cloud.fields.push_back({names[a], layout.offsets[a], static_cast<std::uint8_t>(layout.coordinate), 1});
  }
  if (layout.rgb) {
    cloud.fields.push_back({"rgb", layout.rgb_offset, static_cast<std::uint8_t>(PointFieldType::float32), 1});
  }
  cloud.is_bigendian = layout.big_endian;
  cloud.point_step = layout.point_step;
  cloud.row_step = cloud.width * layout.point_step + layout.row_padding;
  cloud.data.assign(std::size_t{cloud.row_step} * cloud.height, 0);
  cloud.is_dense = !organized || points.size() == std::size_t{cloud.width} * cloud.height;

  float grey;
  std::memcpy(&grey, &kGrey, sizeof grey);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t slots = std::size_t{cloud.width} * cloud.height;
  std::size_t next = 0;  // the next point to place (organized: pixels increase)
  for (std::size_t slot = 0; slot < slots; ++slot) {
    const bool present = organized ? next < points.size() && grid.pixel[next] == slot : true;
    const Point p = present ? points[next] : Point(nan, nan, nan);
    if (present) ++next;
    const std::size_t row = slot / cloud.width;
    const std::size_t column = slot % cloud.width;
    std::uint8_t* point = cloud.data.data() + row * cloud.row_step + column * cloud.point_step;
    for (int a = 0; a < 3; ++a) {
      std::uint8_t* at = point + layout.offsets[a];
      if (f64) {
        store<double>(at, p[a], layout.big_endian);
      } else {
        store<float>(at, static_cast<float>(p[a]), layout.big_endian);
      }
    }
    if (layout.rgb) store<float>(point + layout.rgb_offset, grey, layout.big_endian);
  }
  return cloud;
}

}  // namespace cloudshape::io
