// Reads the vertices of a PLY file (ascii or binary_little_endian) as a point cloud.
// x, y, z may be float or double in any property order; other properties and elements are skipped.
#pragma once

#include <string>
#include <string_view>

#include "io/cloud_file.hpp"

namespace cloudshape::io {

// `name` is only used in ReadError messages. binary_big_endian is a ReadError ("unsupported").
CloudFile read_ply_buffer(std::string_view data, const std::string& name, const ReadLimits& limits = {});

}  // namespace cloudshape::io
