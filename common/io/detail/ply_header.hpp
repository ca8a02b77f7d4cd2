// The PLY header ("ply", format, element/property declarations, end_header), parsed and checked.
// Shared by the point-cloud reader (vertex element) and the mesh reader (vertex + face elements).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/detail/binary_scalar.hpp"

namespace cloudshape::io::detail {

// binary_big_endian is rejected while parsing, so it never reaches a body reader.
enum class PlyFormat { ascii, binary_little_endian };

struct PlyProperty {
  std::string name;
  Scalar type = Scalar::f32;        // the value type, or the item type of a list
  bool is_list = false;
  Scalar count_type = Scalar::u8;   // lists only; always an integer type
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;          // as declared: unchecked against any limit
  std::vector<PlyProperty> properties;
  std::size_t line = 0;             // of the "element" line, for error messages

  // Index of the named property, or properties.size() when absent.
  std::size_t find(std::string_view property) const;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  // first byte after the end_header line
  std::size_t data_line = 0;    // number of the first line after end_header

  // Index of the named element, or elements.size() when absent.
  std::size_t find(std::string_view element) const;
};

PlyHeader parse_ply_header(std::string_view data, const std::string& name);

}  // namespace cloudshape::io::detail
