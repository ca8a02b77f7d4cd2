// The promises every Mesh reader keeps, checked in one place: finite vertices, at least one
// triangle (indices are range-checked by the format parsers, where the place is known).
#pragma once

#include <string>

#include "io/mesh_reader.hpp"

namespace cloudshape::io::detail {

void check_mesh(const Mesh& mesh, const std::string& name);

}  // namespace cloudshape::io::detail
