// Reads the vertices of a PLY file (ascii or binary_little_endian) as a point cloud.
// x, y, z may be float or double in any property order; other properties and elements are skipped.
#include "io/ply_reader.hpp"

#include <algorithm>

#include "io/detail/input.hpp"
#include "io/detail/ply_body.hpp"
#include "io/detail/ply_header.hpp"

namespace cloudshape::io {

CloudFile read_ply_buffer(std::string_view data, const std::string& name, const ReadLimits& limits) {
  detail::check_buffer(data, name, limits);
  const detail::PlyHeader header = detail::parse_ply_header(data, name);
  detail::PlyContent content = detail::read_ply_body(data, header, name, limits, detail::PlyWant::vertices);

  CloudFile out;
  out.format = header.format == detail::PlyFormat::ascii ? "ply-ascii" : "ply-binary_little_endian";
  out.points = std::move(content.vertices);
  const auto kept = std::remove_if(out.points.begin(), out.points.end(),
                                   [](const Point& p) { return !p.allFinite(); });
  out.non_finite_dropped = static_cast<std::size_t>(out.points.end() - kept);
  out.points.erase(kept, out.points.end());
  return out;
}

}  // namespace cloudshape::io
