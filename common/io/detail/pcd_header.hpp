// The PCD header (VERSION .6/0.7, FIELDS ... DATA), parsed and validated against the ReadLimits.
// After this succeeds every size the body reader needs is known and free of overflow.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/cloud_file.hpp"
#include "io/detail/binary_scalar.hpp"

namespace cloudshape::io::detail {

enum class PcdData { ascii, binary, binary_compressed };

struct PcdField {
  std::string name;
  Scalar type = Scalar::f32;
  std::size_t count = 1;   // values per point (COUNT)
  std::size_t offset = 0;  // byte offset inside one binary point record
};

struct PcdHeader {
  std::vector<PcdField> fields;
  std::size_t points = 0;       // WIDTH * HEIGHT, equal to POINTS, <= max_points
  std::size_t width = 0;        // WIDTH, or POINTS when there is no WIDTH line
  std::size_t height = 1;       // HEIGHT (1 when absent): > 1 for an organized cloud
  std::size_t point_size = 0;   // bytes of one binary point record
  std::size_t values_per_point = 0;  // sum of COUNT: tokens of one ascii data row
  std::size_t data_bytes = 0;   // points * point_size, <= max_bytes
  std::array<std::size_t, 3> xyz{};  // indices into fields
  std::optional<std::size_t> label;  // index of a COUNT-1 field named "label", if any
  PcdData data = PcdData::ascii;
  std::size_t data_offset = 0;  // first byte after the DATA line
  std::size_t data_line = 0;    // number of the first line after the DATA line
};

PcdHeader parse_pcd_header(std::string_view data, const std::string& name, const ReadLimits& limits);

}  // namespace cloudshape::io::detail
