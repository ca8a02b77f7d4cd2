// Walks the body of a PLY file (ascii or binary_little_endian) element by element, keeping vertex
// positions and, when asked, faces as triangles; every other element and property is skipped.
#include "io/detail/ply_body.hpp"

#include <algorithm>
#include <limits>

#include "io/detail/binary_scalar.hpp"
#include "io/detail/input.hpp"
#include "io/detail/ply_ascii_walker.hpp"
#include "io/detail/ply_binary_walker.hpp"
#include "io/detail/ply_walk.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io::detail {
namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

// Which elements and properties matter, resolved once from the header.
struct Plan {
  std::size_t vertex = kNone;
  AxisProperties xyz{};
  std::size_t face = kNone;
  std::size_t indices = kNone;  // property of the face element
  std::size_t last = 0;         // last element that has to be walked
};

Plan make_plan(const PlyHeader& header, const std::string& name, const ReadLimits& limits, PlyWant want) {
  Plan plan;
  plan.vertex = header.find("vertex");
  if (plan.vertex == header.elements.size()) throw ReadError(name, kHeader, "missing element 'vertex'");
  const PlyElement& vertex = header.elements[plan.vertex];
  static constexpr const char* kAxes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    plan.xyz[a] = vertex.find(kAxes[a]);
    if (plan.xyz[a] == vertex.properties.size()) {
      throw ReadError(name, at_line(vertex.line), std::string("missing property '") + kAxes[a] + "' in element 'vertex'");
    }
    if (vertex.properties[plan.xyz[a]].is_list) {
      throw ReadError(name, at_line(vertex.line), std::string("property '") + kAxes[a] + "' is a list, expected a scalar");
    }
  }
  if (vertex.count > limits.max_points) {
    throw ReadError(name, at_line(vertex.line),
                    "declared " + std::to_string(vertex.count) + " vertices, more than the limit of " +
                        std::to_string(limits.max_points));
  }
  plan.last = plan.vertex;
  if (want == PlyWant::vertices) return plan;

  plan.face = header.find("face");
  if (plan.face == header.elements.size()) throw ReadError(name, kHeader, "missing element 'face'");
  const PlyElement& face = header.elements[plan.face];
  plan.indices = face.find("vertex_indices");
  if (plan.indices == face.properties.size()) plan.indices = face.find("vertex_index");
  if (plan.indices == face.properties.size() || !face.properties[plan.indices].is_list) {
    throw ReadError(name, at_line(face.line), "missing list property 'vertex_indices' in element 'face'");
  }
  if (!is_integer(face.properties[plan.indices].type)) {
    throw ReadError(name, at_line(face.line), "face vertex indices must have an integer type");
  }
  if (face.count > limits.max_points) {
    throw ReadError(name, at_line(face.line),
                    "declared " + std::to_string(face.count) + " faces, more than the limit of " +
                        std::to_string(limits.max_points));
  }
  if (vertex.count > std::numeric_limits<std::uint32_t>::max()) {
    throw ReadError(name, at_line(vertex.line), "too many vertices for 32-bit triangle indices");
  }
  plan.last = std::max(plan.vertex, plan.face);
  return plan;
}

// Turns a polygon's index stream into triangles (v0, v[i-1], v[i]) without storing the polygon,
// so a hostile list length costs no memory.
template <typename Walker>
PlyContent walk(Walker& walker, const PlyHeader& header, const Plan& plan) {
  PlyContent content;
  const std::uint64_t vertex_count = header.elements[plan.vertex].count;
  for (std::size_t i = 0; i <= plan.last; ++i) {
    const PlyElement& e = header.elements[i];
    if (i == plan.vertex) {
      walker.vertices(e, plan.xyz, content.vertices);
    } else if (i == plan.face) {
      walker.faces(e, plan.indices, vertex_count, content.triangles);
    } else {
      walker.skip(e);
    }
  }
  return content;
}

}  // namespace

PlyContent read_ply_body(std::string_view data, const PlyHeader& header, const std::string& name,
                         const ReadLimits& limits, PlyWant want) {
  const Plan plan = make_plan(header, name, limits, want);
  if (header.format == PlyFormat::ascii) {
    PlyAsciiWalker walker(data, header, name);
    return walk(walker, header, plan);
  }
  PlyBinaryWalker walker(data, header, name);
  return walk(walker, header, plan);
}

}  // namespace cloudshape::io::detail
