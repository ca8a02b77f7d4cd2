// Reads a point-cloud file of any supported format, chosen by its extension.
// .pcd, .ply, .xyz and .txt (case-insensitive); the per-format buffer readers are in their own headers.
#include "io/cloud_reader.hpp"

#include "io/detail/extension.hpp"
#include "io/detail/input.hpp"
#include "io/pcd_reader.hpp"
#include "io/ply_reader.hpp"
#include "io/xyz_reader.hpp"

namespace cloudshape::io {

CloudFile read_pcd_file(const std::string& path, const ReadLimits& limits) {
  return read_pcd_buffer(detail::read_file_bytes(path, limits), path, limits);
}

CloudFile read_ply_file(const std::string& path, const ReadLimits& limits) {
  return read_ply_buffer(detail::read_file_bytes(path, limits), path, limits);
}

CloudFile read_xyz_file(const std::string& path, const ReadLimits& limits) {
  return read_xyz_buffer(detail::read_file_bytes(path, limits), path, limits);
}

CloudFile read_cloud(const std::string& path, const ReadLimits& limits) {
  const std::string extension = detail::lowercase_extension(path);
  if (extension == ".pcd") return read_pcd_file(path, limits);
  if (extension == ".ply") return read_ply_file(path, limits);
  if (extension == ".xyz" || extension == ".txt") return read_xyz_file(path, limits);
  throw ReadError(path, "file name",
                  "unknown extension " + detail::quoted(extension) + " (expected .pcd, .ply, .xyz or .txt)");
}

}  // namespace cloudshape::io
