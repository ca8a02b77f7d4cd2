// Builds a sensor_msgs/PointCloud2 (plain value) from points, in a chosen byte layout.
// For programs that publish or record clouds as ROS 2 messages, and for tests of every layout.
#pragma once

#include <array>
#include <cstdint>

#include "geometry/point_cloud.hpp"
#include "io/pointcloud2.hpp"

namespace cloudshape::io {

// Where x, y, z (and an optional packed "rgb" FLOAT32) sit in each point. The defaults are a
// depth camera's: float32 x y z rgb, 16 bytes.
struct PointCloud2Layout {
  PointFieldType coordinate = PointFieldType::float32;  // FLOAT32 or FLOAT64
  std::array<std::uint32_t, 3> offsets = {0, 4, 8};      // of x, y, z
  bool rgb = true;
  std::uint32_t rgb_offset = 12;
  std::uint32_t point_step = 16;
  std::uint32_t row_padding = 0;  // bytes after each row: row_step = width * point_step + this
  bool big_endian = false;
};

// The layout of a point of float64 x y z then rgb (point_step 32: padded as drivers align).
PointCloud2Layout float64_layout();

// An organized grid (grid.organized()) gives height rows of width points, the pixels that have
// no point set to NaN; otherwise one row of every point. Throws std::invalid_argument when a
// field does not fit in point_step or the coordinate type is not FLOAT32 or FLOAT64.
PointCloud2 encode_pointcloud2(const PointList& points, const GridLayout& grid,
                               const PointCloud2Layout& layout, const RosHeader& header);

}  // namespace cloudshape::io
