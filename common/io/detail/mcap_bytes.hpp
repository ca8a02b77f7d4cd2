// Appends MCAP's little-endian fields and length-prefixed strings to a byte string.
// The writer builds every record with these, so each record's layout reads like the spec's table.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace cloudshape::io::detail::mcap {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "MCAP fields are written as host bytes");

template <typename T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

inline void put_string(std::string& out, std::string_view s) {
  put<std::uint32_t>(out, static_cast<std::uint32_t>(s.size()));
  out.append(s);
}

inline void put_string_map(std::string& out, const std::map<std::string, std::string>& map) {
  std::string entries;
  for (const auto& [key, value] : map) {
    put_string(entries, key);
    put_string(entries, value);
  }
  put_string(out, entries);
}

// A whole record: opcode, content length, content.
inline void put_record(std::string& out, std::uint8_t opcode, std::string_view content) {
  put<std::uint8_t>(out, opcode);
  put<std::uint64_t>(out, content.size());
  out.append(content);
}

}  // namespace cloudshape::io::detail::mcap
