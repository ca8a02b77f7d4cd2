// Walks binary_little_endian PLY records: bulk copies for fixed-size elements, one property at
// a time for elements with lists. Every read is bounds-checked against the buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "geometry/point_cloud.hpp"
#include "io/detail/ply_walk.hpp"

namespace cloudshape::io::detail {

class PlyBinaryWalker {
public:
  PlyBinaryWalker(std::string_view data, const PlyHeader& header, const std::string& name);

  void skip(const PlyElement& e);
  void vertices(const PlyElement& e, const AxisProperties& xyz, PointList& out);
  void faces(const PlyElement& e, std::size_t indices, std::uint64_t vertex_count, Triangles& out);

private:
  [[noreturn]] void truncated(const PlyElement& e, std::uint64_t record) const;
  const unsigned char* take(std::size_t n, const PlyElement& e, std::uint64_t record);
  const unsigned char* bulk(const PlyElement& e, std::size_t record_size);
  std::size_t list_bytes(std::uint64_t n, std::size_t item, const PlyElement& e, std::uint64_t record) const;
  std::uint64_t list_length(const PlyProperty& p, const PlyElement& e, std::uint64_t record);
  void skip_property(const PlyProperty& p, const PlyElement& e, std::uint64_t record);

  const unsigned char* base_;
  std::size_t size_;
  std::size_t pos_;
  const std::string& name_;
};

}  // namespace cloudshape::io::detail
