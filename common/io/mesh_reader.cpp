// Reads triangle meshes (.obj, and .ply with a face element) for surface sampling.
// Polygons are fan-triangulated; every index is checked against the vertex count.
#include "io/mesh_reader.hpp"

#include "io/detail/extension.hpp"
#include "io/detail/input.hpp"
#include "io/detail/mesh_checks.hpp"
#include "io/detail/ply_body.hpp"
#include "io/detail/ply_header.hpp"

namespace cloudshape::io {

Mesh read_ply_mesh_buffer(std::string_view data, const std::string& name, const ReadLimits& limits) {
  detail::check_buffer(data, name, limits);
  const detail::PlyHeader header = detail::parse_ply_header(data, name);
  detail::PlyContent content =
      detail::read_ply_body(data, header, name, limits, detail::PlyWant::vertices_and_faces);
  Mesh mesh{std::move(content.vertices), std::move(content.triangles)};
  detail::check_mesh(mesh, name);
  return mesh;
}

Mesh read_mesh(const std::string& path, const ReadLimits& limits) {
  const std::string extension = detail::lowercase_extension(path);
  if (extension != ".obj" && extension != ".ply") {
    throw ReadError(path, "file name", "unknown mesh extension " + detail::quoted(extension) +
                                           " (expected .obj or .ply)");
  }
  const std::string bytes = detail::read_file_bytes(path, limits);
  return extension == ".obj" ? read_obj_mesh_buffer(bytes, path, limits)
                             : read_ply_mesh_buffer(bytes, path, limits);
}

}  // namespace cloudshape::io
