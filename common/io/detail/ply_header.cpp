// The PLY header ("ply", format, element/property declarations, end_header), parsed and checked.
// Shared by the point-cloud reader (vertex element) and the mesh reader (vertex + face elements).
#include "io/detail/ply_header.hpp"

#include <optional>

#include "io/detail/input.hpp"
#include "io/detail/parse_number.hpp"
#include "io/detail/text_lines.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io::detail {
namespace {

std::optional<Scalar> ply_scalar(std::string_view type) {
  struct Named {
    std::string_view name;
    Scalar scalar;
  };
  // Both the original names and the sized aliases newer writers use.
  static constexpr Named kTypes[] = {
      {"char", Scalar::i8},    {"int8", Scalar::i8},     {"uchar", Scalar::u8},   {"uint8", Scalar::u8},
      {"short", Scalar::i16},  {"int16", Scalar::i16},   {"ushort", Scalar::u16}, {"uint16", Scalar::u16},
      {"int", Scalar::i32},    {"int32", Scalar::i32},   {"uint", Scalar::u32},   {"uint32", Scalar::u32},
      {"float", Scalar::f32},  {"float32", Scalar::f32}, {"double", Scalar::f64}, {"float64", Scalar::f64},
      {"int64", Scalar::i64},  {"uint64", Scalar::u64},
  };
  for (const auto& t : kTypes) {
    if (t.name == type) return t.scalar;
  }
  return std::nullopt;
}

std::vector<std::string_view> tokens_of(std::string_view line) {
  std::vector<std::string_view> out;
  TokenCursor cursor(line);
  std::string_view token;
  while (cursor.next(token)) out.push_back(token);
  return out;
}

}  // namespace

std::size_t PlyElement::find(std::string_view property) const {
  std::size_t i = 0;
  while (i < properties.size() && properties[i].name != property) ++i;
  return i;
}

std::size_t PlyHeader::find(std::string_view element) const {
  std::size_t i = 0;
  while (i < elements.size() && elements[i].name != element) ++i;
  return i;
}

PlyHeader parse_ply_header(std::string_view data, const std::string& name) {
  LineCursor lines(data);
  std::string_view line;
  if (!lines.next(line) || tokens_of(line) != std::vector<std::string_view>{"ply"}) {
    throw ReadError(name, at_line(1), "not a PLY file (the first line must be 'ply')");
  }
  PlyHeader header;
  bool have_format = false;
  while (lines.next(line)) {
    const std::string place = at_line(lines.line_number());
    const auto tokens = tokens_of(line);
    if (tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info") continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "end_header") {
      if (!have_format) throw ReadError(name, kHeader, "no format line");
      header.data_offset = lines.offset();
      header.data_line = lines.next_line_number();
      return header;
    }
    if (keyword == "format") {
      if (tokens.size() != 3) throw ReadError(name, place, "format line needs a kind and a version");
      if (tokens[1] == "ascii") {
        header.format = PlyFormat::ascii;
      } else if (tokens[1] == "binary_little_endian") {
        header.format = PlyFormat::binary_little_endian;
      } else if (tokens[1] == "binary_big_endian") {
        throw ReadError(name, place, "unsupported format binary_big_endian (use ascii or binary_little_endian)");
      } else {
        throw ReadError(name, place, "unknown format " + quoted(tokens[1]));
      }
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      if (tokens.size() != 3 || !parse_uint(tokens[2], element.count)) {
        throw ReadError(name, place, "element line needs a name and a non-negative integer count");
      }
      element.name = std::string(tokens[1]);
      element.line = lines.line_number();
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) throw ReadError(name, place, "property before any element");
      PlyProperty property;
      if (tokens.size() == 5 && tokens[1] == "list") {
        const auto count_type = ply_scalar(tokens[2]);
        const auto item_type = ply_scalar(tokens[3]);
        if (!count_type || !is_integer(*count_type)) {
          throw ReadError(name, place, "list count type " + quoted(tokens[2]) + " is not an integer type");
        }
        if (!item_type) throw ReadError(name, place, "unknown property type " + quoted(tokens[3]));
        property.is_list = true;
        property.count_type = *count_type;
        property.type = *item_type;
        property.name = std::string(tokens[4]);
      } else if (tokens.size() == 3) {
        const auto type = ply_scalar(tokens[1]);
        if (!type) throw ReadError(name, place, "unknown property type " + quoted(tokens[1]));
        property.type = *type;
        property.name = std::string(tokens[2]);
      } else {
        throw ReadError(name, place, "malformed property line");
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {
      throw ReadError(name, place, "unknown header keyword " + quoted(keyword));
    }
  }
  throw ReadError(name, kHeader, "no end_header line: the header is cut short");
}

}  // namespace cloudshape::io::detail
