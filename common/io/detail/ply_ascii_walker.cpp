// Walks ascii PLY records: one record per line, whitespace-separated values, each checked to be
// a number, with the line number in every error.
#include "io/detail/ply_ascii_walker.hpp"

#include <algorithm>

#include "io/detail/binary_scalar.hpp"
#include "io/detail/parse_number.hpp"

namespace cloudshape::io::detail {

PlyAsciiWalker::PlyAsciiWalker(std::string_view data, const PlyHeader& header, const std::string& name)
    : lines_(data, header.data_offset, header.data_line), size_(data.size()), name_(name) {}

void PlyAsciiWalker::skip(const PlyElement& e) {
  if (e.properties.empty()) return;  // such records have no line of their own
  std::string_view line;
  for (std::uint64_t r = 0; r < e.count; ++r) next_record(e, r, line);
}

void PlyAsciiWalker::vertices(const PlyElement& e, const AxisProperties& xyz, PointList& out) {
  // A vertex line holds at least "x y z\n"; reserve no more than the bytes can carry.
  out.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(e.count, (size_ - lines_.offset()) / 6 + 1)));
  std::string_view line;
  for (std::uint64_t r = 0; r < e.count; ++r) {
    next_record(e, r, line);
    TokenCursor tokens(line);
    double values[3] = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const PlyProperty& p = e.properties[i];
      if (p.is_list) {
        skip_list(tokens, p, e);
        continue;
      }
      const double value = number(tokens, p, e);
      for (int a = 0; a < 3; ++a) {
        if (xyz[a] == i) values[a] = value;
      }
    }
    expect_end(tokens, e);
    out.emplace_back(values[0], values[1], values[2]);
  }
}

void PlyAsciiWalker::faces(const PlyElement& e, std::size_t indices, std::uint64_t vertex_count, Triangles& out) {
  out.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(e.count, (size_ - lines_.offset()) / 8 + 1)));
  std::string_view line;
  for (std::uint64_t r = 0; r < e.count; ++r) {
    next_record(e, r, line);
    TokenCursor tokens(line);
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const PlyProperty& p = e.properties[i];
      if (i != indices) {
        if (p.is_list) {
          skip_list(tokens, p, e);
        } else {
          number(tokens, p, e);
        }
        continue;
      }
      const std::uint64_t n = length(tokens, p, e);
      TriangleFan fan;
      for (std::uint64_t k = 0; k < n; ++k) {
        const std::string_view token = next_token(tokens, p, e);
        std::uint64_t index = 0;
        if (!parse_uint(token, index)) {
          throw ReadError(name_, here(), "face " + std::to_string(r) + ": invalid vertex index " + quoted(token));
        }
        if (index >= vertex_count) throw_index_out_of_range(name_, here(), r, index, vertex_count);
        fan.add(static_cast<std::uint32_t>(index), out);
      }
    }
    expect_end(tokens, e);
  }
}

std::string PlyAsciiWalker::here() const { return at_line(lines_.line_number()); }

void PlyAsciiWalker::next_record(const PlyElement& e, std::uint64_t record, std::string_view& line) {
  while (lines_.next(line)) {
    if (!is_blank(line)) return;
  }
  throw ReadError(name_, at_line(lines_.next_line_number()),
                  "header/data count mismatch: " + element_name(e) + " declares " + std::to_string(e.count) +
                      " records, found " + std::to_string(record));
}

std::string_view PlyAsciiWalker::next_token(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e) {
  std::string_view token;
  if (!tokens.next(token)) {
    throw ReadError(name_, here(), "too few values for " + element_name(e) + " (property " + quoted(p.name) + ")");
  }
  return token;
}

double PlyAsciiWalker::number(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e) {
  const std::string_view token = next_token(tokens, p, e);
  double value = 0.0;
  if (!parse_double(token, value)) {
    throw ReadError(name_, here(),
                    "non-numeric value " + quoted(token) + " for property " + quoted(p.name) + " of " + element_name(e));
  }
  return as_declared(value, p.type);
}

std::uint64_t PlyAsciiWalker::length(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e) {
  const std::string_view token = next_token(tokens, p, e);
  std::uint64_t n = 0;
  if (!parse_uint(token, n)) {
    throw ReadError(name_, here(), "invalid list length " + quoted(token) + " for property " + quoted(p.name));
  }
  return n;
}

// The loop ends at the line's last token, so a huge declared length cannot spin.
void PlyAsciiWalker::skip_list(TokenCursor& tokens, const PlyProperty& p, const PlyElement& e) {
  const std::uint64_t n = length(tokens, p, e);
  for (std::uint64_t k = 0; k < n; ++k) number(tokens, p, e);
}

void PlyAsciiWalker::expect_end(TokenCursor& tokens, const PlyElement& e) {
  if (!tokens.at_end()) throw ReadError(name_, here(), "too many values for " + element_name(e));
}

}  // namespace cloudshape::io::detail
