// Walks the body of a PLY file (ascii or binary_little_endian) element by element, keeping vertex
// positions and, when asked, faces as triangles; every other element and property is skipped.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "io/cloud_file.hpp"
#include "io/detail/ply_header.hpp"

namespace cloudshape::io::detail {

enum class PlyWant { vertices, vertices_and_faces };

struct PlyContent {
  PointList vertices;  // every vertex in file order, finite or not: faces index into them
  std::vector<std::array<std::uint32_t, 3>> triangles;  // polygons fan-triangulated
};

// Needs an element "vertex" with scalar properties x, y, z, and for faces an element "face"
// with a list property "vertex_indices" (or "vertex_index"). Elements after the last one
// needed are never looked at. Throws ReadError.
PlyContent read_ply_body(std::string_view data, const PlyHeader& header, const std::string& name,
                         const ReadLimits& limits, PlyWant want);

}  // namespace cloudshape::io::detail
