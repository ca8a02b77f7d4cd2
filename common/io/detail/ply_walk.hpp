// Pieces shared by the ascii and the binary PLY body walkers: what to extract, polygon fans,
// and the wording of element errors.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/detail/input.hpp"
#include "io/detail/ply_header.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io::detail {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;
using AxisProperties = std::array<std::size_t, 3>;  // indices of x, y, z in the vertex element

inline std::string element_name(const PlyElement& e) { return "element " + quoted(e.name); }

[[noreturn]] inline void throw_index_out_of_range(const std::string& name, const std::string& place,
                                                  std::uint64_t face, std::uint64_t index,
                                                  std::uint64_t vertices) {
  throw ReadError(name, place, "face " + std::to_string(face) + ": vertex index " + std::to_string(index) +
                                   " out of range (" + std::to_string(vertices) + " vertices)");
}

// Turns a polygon's index stream into triangles (v0, v[i-1], v[i]) without storing the polygon,
// so a hostile list length costs no memory.
class TriangleFan {
public:
  void add(std::uint32_t index, Triangles& out) {
    if (seen_ == 0) {
      first_ = index;
    } else if (seen_ >= 2) {
      out.push_back({first_, previous_, index});
    }
    previous_ = index;
    ++seen_;
  }

private:
  std::uint64_t seen_ = 0;
  std::uint32_t first_ = 0;
  std::uint32_t previous_ = 0;
};

}  // namespace cloudshape::io::detail
