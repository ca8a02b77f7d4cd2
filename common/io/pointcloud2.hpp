// ROS 2 sensor_msgs/PointCloud2 as a plain value, and its decoding into the cloud every reader returns.
// No middleware types: the DDS ingest and a recording's reader both fill a PointCloud2 and decode it here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/cloud_file.hpp"

namespace cloudshape::io {

// builtin_interfaces/Time and std_msgs/Header.
struct RosTime {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
};

struct RosHeader {
  RosTime stamp;
  std::string frame_id;
};

// sensor_msgs/PointField: the datatype codes are ROS's.
enum class PointFieldType : std::uint8_t {
  int8 = 1,
  uint8 = 2,
  int16 = 3,
  uint16 = 4,
  int32 = 5,
  uint32 = 6,
  float32 = 7,
  float64 = 8
};

struct PointField {
  std::string name;
  std::uint32_t offset = 0;  // bytes from the start of a point
  std::uint8_t datatype = 0;  // a PointFieldType code
  std::uint32_t count = 1;    // elements of that type
};

// sensor_msgs/PointCloud2, field for field.
struct PointCloud2 {
  RosHeader header;
  std::uint32_t height = 0;  // rows: 1 for an unorganized cloud
  std::uint32_t width = 0;   // points per row
  std::vector<PointField> fields;
  bool is_bigendian = false;
  std::uint32_t point_step = 0;  // bytes per point
  std::uint32_t row_step = 0;    // bytes per row
  std::vector<std::uint8_t> data;
  bool is_dense = false;
};

// The name ROS gives a datatype code ("FLOAT32"), or "datatype N" for a code it does not define.
std::string point_field_type_name(std::uint8_t datatype);

// The points of `cloud`: fields "x", "y" and "z" (FLOAT32 or FLOAT64, count 1, at any offset;
// other fields ignored), either byte order, rows row_step apart. Points with a NaN or infinite
// coordinate are dropped and counted; when height > 1 the grid is kept (pixel = row * width +
// column of each kept point), as the PCD reader keeps it. format is "ros2-pointcloud2".
// Throws ReadError("<name>", "<place>", "<problem>") when x, y or z is missing, repeated, of
// another type or count, when a field's datatype is unknown or its values run past point_step
// (so a point_step of 0 is refused too), when width * point_step exceeds row_step, when
// data is not exactly row_step * height bytes, or when width * height exceeds limits.max_points
// (or the 32-bit pixel index of an organized cloud) or data exceeds limits.max_bytes.
CloudFile decode_pointcloud2(const PointCloud2& cloud, const std::string& name,
                             const ReadLimits& limits = {});

}  // namespace cloudshape::io
