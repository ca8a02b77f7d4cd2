// Locale-free, allocation-free number parsing shared by the text readers (PCD ascii, PLY ascii, XYZ).
// Built on std::from_chars so a value costs a few nanoseconds and never touches iostreams.
#pragma once

#include <charconv>
#include <cstdint>
#include <limits>
#include <string_view>
#include <system_error>

namespace cloudshape::io::detail {

// For a syntactically valid decimal that from_chars called out of range: true when it is
// too large for a double, false when it is too small (an underflow towards zero).
inline bool out_of_range_is_overflow(std::string_view token) {
  std::size_t i = 0;
  if (i < token.size() && (token[i] == '-' || token[i] == '+')) ++i;
  long integer_digits = 0;     // significant digits before the point
  long fraction_zeros = 0;     // zeros between the point and the first significant digit
  bool significant = false;
  bool in_fraction = false;
  for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
    const char c = token[i];
    if (c == '.') {
      in_fraction = true;
    } else if (!in_fraction) {
      significant = significant || c != '0';
      if (significant) ++integer_digits;
    } else if (!significant) {
      if (c == '0') ++fraction_zeros; else significant = true;
    }
  }
  long exponent = 0;
  if (i + 1 < token.size()) {
    std::string_view digits = token.substr(i + 1);
    const bool negative = digits.front() == '-';
    if (digits.front() == '-' || digits.front() == '+') digits.remove_prefix(1);
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
    if (r.ec == std::errc::result_out_of_range) exponent = std::numeric_limits<long>::max() / 2;
    if (negative) exponent = -exponent;
  }
  const long magnitude = integer_digits > 0 ? integer_digits + exponent : exponent - fraction_zeros;
  return magnitude > 0;
}

// The whole token must be a number; "1.5abc" is rejected rather than read as 1.5.
// A leading '+' is accepted because other writers emit it, although from_chars does not.
// "nan", "inf" and "infinity" are accepted: non-finite values are counted, not errors.
inline bool parse_double(std::string_view token, double& value) {
  if (token.size() > 1 && token.front() == '+' && token[1] != '-' && token[1] != '+') {
    token.remove_prefix(1);
  }
  if (token.empty()) return false;
  const char* const end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  if (result.ec == std::errc::result_out_of_range && result.ptr == end) {
    // Same outcome as strtod: overflow becomes infinity (later dropped as non-finite),
    // underflow becomes zero; neither fails the file.
    const bool negative = token.front() == '-';
    if (out_of_range_is_overflow(token)) {
      value = negative ? -std::numeric_limits<double>::infinity()
                       : std::numeric_limits<double>::infinity();
    } else {
      value = negative ? -0.0 : 0.0;
    }
    return true;
  }
  return result.ec == std::errc() && result.ptr == end;
}

inline bool parse_uint(std::string_view token, std::uint64_t& value) {
  if (token.size() > 1 && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* const end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

}  // namespace cloudshape::io::detail
