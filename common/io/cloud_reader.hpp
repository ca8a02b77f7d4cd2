// Reads a point-cloud file of any supported format, chosen by its extension.
// .pcd, .ply, .xyz and .txt (case-insensitive); the per-format buffer readers are in their own headers.
#pragma once

#include <string>

#include "io/cloud_file.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io {

// Throws ReadError for an unknown extension, a file that cannot be opened, an empty or
// over-limit file, and anything the format's reader rejects. Messages name `path` as given.
CloudFile read_cloud(const std::string& path, const ReadLimits& limits = {});

// One format whatever the extension, for files named by other conventions.
CloudFile read_pcd_file(const std::string& path, const ReadLimits& limits = {});
CloudFile read_ply_file(const std::string& path, const ReadLimits& limits = {});
CloudFile read_xyz_file(const std::string& path, const ReadLimits& limits = {});

}  // namespace cloudshape::io
