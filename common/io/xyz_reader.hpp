// Reads plain-text point clouds: one "x y z" per line (.xyz, .txt).
// Spaces, tabs or commas separate values; extra columns, blank lines and '#' lines are ignored.
#pragma once

#include <string>
#include <string_view>

#include "io/cloud_file.hpp"

namespace cloudshape::io {

// `name` is only used in ReadError messages. A line with fewer than three values or a
// non-numeric x, y or z is a ReadError naming the line.
CloudFile read_xyz_buffer(std::string_view data, const std::string& name, const ReadLimits& limits = {});

}  // namespace cloudshape::io
