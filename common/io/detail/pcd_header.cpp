// The PCD header (VERSION .6/0.7, FIELDS ... DATA), parsed and validated against the ReadLimits.
// After this succeeds every size the body reader needs is known and free of overflow.
#include "io/detail/pcd_header.hpp"

#include <cctype>
#include <cstdint>
#include <optional>

#include "io/detail/input.hpp"
#include "io/detail/parse_number.hpp"
#include "io/detail/text_lines.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io::detail {
namespace {

// Per-keyword values as written, before they are checked against each other.
struct RawHeader {
  std::vector<std::string> names;
  std::vector<std::uint64_t> sizes;
  std::vector<std::string> types;
  std::vector<std::uint64_t> counts;
  std::size_t fields_line = 0, size_line = 0, type_line = 0, count_line = 0;
  std::optional<std::uint64_t> width, height, points;
  std::optional<PcdData> data;
};

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

class HeaderParser {
public:
  HeaderParser(std::string_view data, const std::string& name, const ReadLimits& limits)
      : data_(data), name_(name), limits_(limits) {}

  PcdHeader parse() {
    LineCursor lines(data_);
    std::string_view line;
    while (!raw_.data && lines.next(line)) {
      line_ = lines.line_number();
      TokenCursor tokens(line);
      std::string_view keyword;
      if (!tokens.next(keyword) || keyword.front() == '#') continue;
      read_keyword(keyword, tokens);
      if (raw_.data) {
        header_.data_offset = lines.offset();
        header_.data_line = lines.next_line_number();
      }
    }
    if (!raw_.data) fail(kHeader, "no DATA line: not a PCD file or the header is cut short");
    header_.data = *raw_.data;
    build_fields();
    find_xyz();
    settle_point_count();
    if (header_.data != PcdData::ascii) settle_data_bytes();
    return header_;
  }

private:
  [[noreturn]] void fail(const std::string& place, const std::string& problem) const {
    throw ReadError(name_, place, problem);
  }
  [[noreturn]] void fail_here(const std::string& problem) const { fail(at_line(line_), problem); }

  // Lines that default (no SIZE/TYPE/COUNT in a .6 file) have number 0.
  static std::string place(std::size_t line) { return line ? at_line(line) : std::string(kHeader); }

  std::vector<std::string_view> rest(TokenCursor& tokens) const {
    std::vector<std::string_view> values;
    std::string_view token;
    while (tokens.next(token)) values.push_back(token);
    return values;
  }

  std::vector<std::uint64_t> unsigned_list(TokenCursor& tokens, const std::string& keyword) const {
    std::vector<std::uint64_t> values;
    for (const auto token : rest(tokens)) {
      std::uint64_t v = 0;
      if (!parse_uint(token, v)) {
        fail_here("non-numeric value " + quoted(token) + " in " + keyword +
                  " (expected a non-negative integer)");
      }
      values.push_back(v);
    }
    return values;
  }

  std::uint64_t single_unsigned(TokenCursor& tokens, const std::string& keyword) const {
    const auto values = unsigned_list(tokens, keyword);
    if (values.size() != 1) fail_here(keyword + " needs exactly one value");
    return values.front();
  }

  void read_keyword(std::string_view written, TokenCursor& tokens) {
    const std::string keyword = upper(written);
    if (keyword == "VERSION" || keyword == "VIEWPOINT") {
      return;  // Neither changes how points are read.
    } else if (keyword == "FIELDS" || keyword == "COLUMNS") {  // COLUMNS: PCD .5/.6
      raw_.names.clear();
      for (const auto token : rest(tokens)) raw_.names.emplace_back(token);
      raw_.fields_line = line_;
    } else if (keyword == "SIZE") {
      raw_.sizes = unsigned_list(tokens, keyword);
      raw_.size_line = line_;
    } else if (keyword == "TYPE") {
      raw_.types.clear();
      for (const auto token : rest(tokens)) raw_.types.emplace_back(token);
      raw_.type_line = line_;
    } else if (keyword == "COUNT") {
      raw_.counts = unsigned_list(tokens, keyword);
      raw_.count_line = line_;
    } else if (keyword == "WIDTH") {
      raw_.width = single_unsigned(tokens, keyword);
    } else if (keyword == "HEIGHT") {
      raw_.height = single_unsigned(tokens, keyword);
    } else if (keyword == "POINTS") {
      raw_.points = single_unsigned(tokens, keyword);
    } else if (keyword == "DATA") {
      const auto values = rest(tokens);
      const std::string kind = values.size() == 1 ? upper(values.front()) : std::string();
      if (kind == "ASCII") {
        raw_.data = PcdData::ascii;
      } else if (kind == "BINARY") {
        raw_.data = PcdData::binary;
      } else if (kind == "BINARY_COMPRESSED") {
        raw_.data = PcdData::binary_compressed;
      } else {
        fail_here("unknown DATA kind " + quoted(values.empty() ? std::string_view() : values.front()) +
                  " (expected ascii, binary or binary_compressed)");
      }
    } else {
      fail_here("unknown header keyword " + quoted(written) + ": not a PCD file?");
    }
  }

  static std::optional<Scalar> scalar_for(char type, std::uint64_t size) {
    switch (type) {
      case 'F': return size == 4 ? std::optional(Scalar::f32) : size == 8 ? std::optional(Scalar::f64) : std::nullopt;
      case 'I':
        switch (size) {
          case 1: return Scalar::i8;
          case 2: return Scalar::i16;
          case 4: return Scalar::i32;
          case 8: return Scalar::i64;
          default: return std::nullopt;
        }
      case 'U':
        switch (size) {
          case 1: return Scalar::u8;
          case 2: return Scalar::u16;
          case 4: return Scalar::u32;
          case 8: return Scalar::u64;
          default: return std::nullopt;
        }
      default: return std::nullopt;
    }
  }

  void check_list_length(std::size_t got, std::size_t line, const char* keyword) const {
    if (got != raw_.names.size()) {
      fail(at_line(line), std::string(keyword) + " has " + std::to_string(got) + " values for " +
                              std::to_string(raw_.names.size()) + " FIELDS");
    }
  }

  // Missing SIZE/TYPE/COUNT lines (PCD .6 files) default to one 4-byte float each.
  void build_fields() {
    const std::size_t n = raw_.names.size();
    if (n == 0) fail(kHeader, "no FIELDS line");
    if (raw_.size_line) check_list_length(raw_.sizes.size(), raw_.size_line, "SIZE");
    if (raw_.type_line) check_list_length(raw_.types.size(), raw_.type_line, "TYPE");
    if (raw_.count_line) check_list_length(raw_.counts.size(), raw_.count_line, "COUNT");

    std::size_t offset = 0;
    std::size_t values = 0;
    header_.fields.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      PcdField& field = header_.fields[i];
      field.name = raw_.names[i];
      const std::uint64_t size = raw_.size_line ? raw_.sizes[i] : 4;
      const std::string type = raw_.type_line ? upper(raw_.types[i]) : "F";
      const auto scalar = type.size() == 1 ? scalar_for(type.front(), size) : std::nullopt;
      if (!scalar) {
        fail(place(raw_.type_line ? raw_.type_line : raw_.size_line),
             "field " + quoted(field.name) + " has unsupported TYPE " + quoted(type) + " with SIZE " +
                 std::to_string(size));
      }
      field.type = *scalar;
      const std::uint64_t count = raw_.count_line ? raw_.counts[i] : 1;
      if (count == 0) fail(place(raw_.count_line), "field " + quoted(field.name) + " has COUNT 0");
      std::uint64_t bytes = 0;
      if (__builtin_mul_overflow(count, size, &bytes) || __builtin_add_overflow(offset, bytes, &bytes) ||
          bytes > limits_.max_bytes) {
        fail(place(raw_.count_line), "point record size exceeds the limit of " +
                                           std::to_string(limits_.max_bytes) + " bytes");
      }
      field.count = static_cast<std::size_t>(count);
      field.offset = offset;
      offset = static_cast<std::size_t>(bytes);
      values += field.count;  // cannot overflow: bounded by the byte total above
    }
    header_.point_size = offset;
    header_.values_per_point = values;
  }

  void find_xyz() {
    static constexpr const char* kAxes[3] = {"x", "y", "z"};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      std::size_t i = 0;
      while (i < header_.fields.size() && header_.fields[i].name != kAxes[axis]) ++i;
      if (i == header_.fields.size()) {
        std::string listed;
        for (const auto& f : header_.fields) listed += (listed.empty() ? "" : " ") + f.name;
        fail(place(raw_.fields_line),
             std::string("missing field '") + kAxes[axis] + "' (FIELDS " + quoted(listed) + ")");
      }
      if (header_.fields[i].count != 1) {
        fail(place(raw_.count_line), std::string("field '") + kAxes[axis] + "' has COUNT " +
                                           std::to_string(header_.fields[i].count) + ", expected 1");
      }
      header_.xyz[axis] = i;
    }
    for (std::size_t i = 0; i < header_.fields.size(); ++i) {
      if (header_.fields[i].name == "label" && header_.fields[i].count == 1) header_.label = i;
    }
  }

  [[noreturn]] void too_many_points(std::uint64_t declared) const {
    fail(kHeader, "declared " + std::to_string(declared) + " points, more than the limit of " +
                      std::to_string(limits_.max_points));
  }

  void settle_point_count() {
    std::uint64_t points = 0;
    if (raw_.width) {
      const std::uint64_t height = raw_.height.value_or(1);
      if (__builtin_mul_overflow(*raw_.width, height, &points)) too_many_points(UINT64_MAX);
      if (raw_.points && *raw_.points != points) {
        fail(kHeader, "header/data count mismatch: WIDTH " + std::to_string(*raw_.width) +
                          " x HEIGHT " + std::to_string(height) + " = " + std::to_string(points) +
                          " but POINTS " + std::to_string(*raw_.points));
      }
    } else if (raw_.points) {
      points = *raw_.points;
    } else {
      fail(kHeader, "no POINTS or WIDTH line");
    }
    if (points > limits_.max_points) too_many_points(points);
    header_.points = static_cast<std::size_t>(points);
    header_.height = raw_.width ? static_cast<std::size_t>(raw_.height.value_or(1)) : 1;
    header_.width = header_.height > 0 ? header_.points / header_.height : 0;
  }

  void settle_data_bytes() {
    std::size_t bytes = 0;
    if (__builtin_mul_overflow(header_.points, header_.point_size, &bytes) || bytes > limits_.max_bytes) {
      fail(kHeader, "declared " + std::to_string(header_.points) + " points of " +
                        std::to_string(header_.point_size) + " bytes, more than the limit of " +
                        std::to_string(limits_.max_bytes) + " bytes");
    }
    header_.data_bytes = bytes;
  }

  std::string_view data_;
  const std::string& name_;
  const ReadLimits& limits_;
  std::size_t line_ = 0;
  RawHeader raw_;
  PcdHeader header_;
};

}  // namespace

PcdHeader parse_pcd_header(std::string_view data, const std::string& name, const ReadLimits& limits) {
  return HeaderParser(data, name, limits).parse();
}

}  // namespace cloudshape::io::detail
