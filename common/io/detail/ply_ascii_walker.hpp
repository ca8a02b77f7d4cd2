// Walks ascii PLY records: one record per line, whitespace-separated values, each checked to be
// a number, with the line number in every error.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "geometry/point_cloud.hpp"
#include "io/detail/ply_walk.hpp"
#include "io/detail/text_lines.hpp"

namespace cloudshape::io::detail {

class PlyAsciiWalker {
public:
  PlyAsciiWalker(std::string_view data, const PlyHeader& header, const std::string& name);

  void skip(const PlyElement& e);
  void vertices(const PlyElement& e, const AxisProperties& xyz, PointList& out);
  void faces(const PlyElement& e, std::size_t indices, std::uint64_t vertex_count, Triangles& out);

private:
  std::string here() const;
  void next_record(const PlyElement& e, std::uint64_t record, std::string_view& line);
  std::string_view next_token(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e);
  double number(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e);
  std::uint64_t length(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e);
  void skip_list(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e);
  void expect_end(TokenCursor& tokens, const PlyElement& e);

  LineCursor lines_;
  std::size_t size_;
  const std::string& name_;
};

}  // namespace cloudshape::io::detail
