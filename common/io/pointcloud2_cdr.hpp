// A ROS 2 sensor_msgs/msg/PointCloud2 as CDR bytes (a recording's message) to and from the plain
// PointCloud2 value that decode_pointcloud2 turns into a cloud.
#pragma once

#include <string>
#include <string_view>

#include "io/cloud_file.hpp"
#include "io/pointcloud2.hpp"

namespace cloudshape::io {

// ReadError(name, place, "CDR: ...") when the bytes are not a whole PointCloud2 (short, a
// lying sequence length, a string without its NUL) or the data exceeds limits.max_bytes.
// Bytes after the last field are allowed: CDR pads messages to four bytes.
PointCloud2 pointcloud2_from_cdr(std::string_view bytes, const std::string& name, const std::string& place,
                                 const ReadLimits& limits = {});

// Little-endian CDR with its encapsulation header, as ROS 2 publishes and records it.
std::string pointcloud2_to_cdr(const PointCloud2& cloud);

}  // namespace cloudshape::io
