// Reads PCD point clouds (DATA ascii, binary or binary_compressed) into x/y/z points.
// x, y and z at any field position; non-finite points dropped and counted, pixels and labels kept.
#pragma once

#include <string>
#include <string_view>

#include "io/cloud_file.hpp"

namespace cloudshape::io {

// `name` is only used in ReadError messages. Throws ReadError on any malformed input.
CloudFile read_pcd_buffer(std::string_view data, const std::string& name, const ReadLimits& limits = {});

}  // namespace cloudshape::io
