// Reads Wavefront OBJ meshes through tinyobjloader: positions and faces only.
// Materials, normals and texture coordinates are not needed for surface sampling and are not loaded.
#include <tiny_obj_loader.h>

#include <cctype>
#include <sstream>

#include "io/detail/input.hpp"
#include "io/detail/mesh_checks.hpp"
#include "io/mesh_reader.hpp"

namespace cloudshape::io {
namespace {

// tinyobjloader reports "... line 12 ..." inside free text; surface it as the place.
std::string place_in(const std::string& message) {
  for (auto at = message.find("line "); at != std::string::npos; at = message.find("line ", at + 1)) {
    std::size_t end = at + 5;
    while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
    if (end > at + 5) return message.substr(at, end - at);
  }
  return "data";
}

std::string first_line(const std::string& message) {
  std::string line = message.substr(0, message.find('\n'));
  return line.empty() ? "tinyobjloader failed without a message" : line;
}

}  // namespace

Mesh read_obj_mesh_buffer(std::string_view data, const std::string& name, const ReadLimits& limits) {
  detail::check_buffer(data, name, limits);
  std::istringstream stream{std::string(data)};
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warnings;
  std::string errors;
  // No material reader: a missing .mtl must not fail a geometry read, and a mesh file
  // should not make the reader open other files. Triangulation is done below so that
  // indices are validated before any of them is used.
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &stream, nullptr,
                        /*triangulate=*/false)) {
    throw ReadError(name, place_in(errors), first_line(errors));
  }
  const std::size_t vertex_count = attrib.vertices.size() / 3;
  if (vertex_count > limits.max_points) {
    throw ReadError(name, "data", std::to_string(vertex_count) + " vertices, more than the limit of " +
                                      std::to_string(limits.max_points));
  }
  Mesh mesh;
  mesh.vertices.reserve(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) {
    mesh.vertices.emplace_back(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
  }
  std::size_t face = 0;
  for (const auto& shape : shapes) {
    std::size_t next = 0;
    for (const auto corners : shape.mesh.num_face_vertices) {
      const std::size_t first = next;
      next += corners;
      if (next > shape.mesh.indices.size()) throw ReadError(name, "face " + std::to_string(face), "truncated face");
      for (std::size_t k = first; k < next; ++k) {
        const int index = shape.mesh.indices[k].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= vertex_count) {
          // OBJ counts from 1 (negative counts back from the latest vertex).
          throw ReadError(name, "face " + std::to_string(face + 1),
                          "vertex index out of range (" + std::to_string(vertex_count) + " vertices)");
        }
      }
      for (std::size_t k = first + 2; k < next; ++k) {
        mesh.triangles.push_back({static_cast<std::uint32_t>(shape.mesh.indices[first].vertex_index),
                                  static_cast<std::uint32_t>(shape.mesh.indices[k - 1].vertex_index),
                                  static_cast<std::uint32_t>(shape.mesh.indices[k].vertex_index)});
      }
      if (mesh.triangles.size() > limits.max_points) {
        throw ReadError(name, "face " + std::to_string(face + 1),
                        "more than the limit of " + std::to_string(limits.max_points) + " triangles");
      }
      ++face;
    }
  }
  detail::check_mesh(mesh, name);
  return mesh;
}

}  // namespace cloudshape::io
