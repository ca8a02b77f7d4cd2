// The promises every Mesh reader keeps, checked in one place: finite vertices, at least one
// triangle (indices are range-checked by the format parsers, where the place is known).
#include "io/detail/mesh_checks.hpp"

namespace cloudshape::io::detail {

void check_mesh(const Mesh& mesh, const std::string& name) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!mesh.vertices[i].allFinite()) {
      throw ReadError(name, "vertex " + std::to_string(i), "non-finite vertex coordinate");
    }
  }
  if (mesh.triangles.empty()) throw ReadError(name, "faces", "no faces: the mesh has no surface to sample");
}

}  // namespace cloudshape::io::detail
