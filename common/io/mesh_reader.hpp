// Reads triangle meshes (.obj, and .ply with a face element) for surface sampling.
// Polygons are fan-triangulated; every index is checked against the vertex count.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "io/cloud_file.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io {

struct Mesh {
  PointList vertices;  // all finite
  std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into vertices, at least one
};

// Chooses the format by extension (.obj or .ply, case-insensitive). Throws ReadError for an
// unreadable file, malformed data, an out-of-range index, a non-finite vertex or no faces.
Mesh read_mesh(const std::string& path, const ReadLimits& limits = {});

// The same from memory; `name` is only used in ReadError messages. limits.max_points
// bounds the vertex and the face count separately.
Mesh read_obj_mesh_buffer(std::string_view data, const std::string& name, const ReadLimits& limits = {});
Mesh read_ply_mesh_buffer(std::string_view data, const std::string& name, const ReadLimits& limits = {});

}  // namespace cloudshape::io
