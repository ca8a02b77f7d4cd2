// Reads the little-endian fields of one MCAP record's content, never past its end.
// Every overrun becomes a ReadError naming the file, the record and the field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>

#include "io/read_error.hpp"

namespace cloudshape::io::detail::mcap {

class RecordCursor {
public:
  // `where` names the record in errors, e.g. "Channel record at byte 1234".
  RecordCursor(std::string_view content, const std::string& file, std::string where)
      : data_(content), file_(file), where_(std::move(where)) {}

  std::uint8_t u8(const char* field) { return load<std::uint8_t>(field); }
  std::uint16_t u16(const char* field) { return load<std::uint16_t>(field); }
  std::uint32_t u32(const char* field) { return load<std::uint32_t>(field); }
  std::uint64_t u64(const char* field) { return load<std::uint64_t>(field); }

  std::string_view take(std::uint64_t n, const char* field) {
    if (n > remaining()) {
      fail("field '" + std::string(field) + "' needs " + std::to_string(n) + " bytes, the record has " +
           std::to_string(remaining()) + " left");
    }
    const std::string_view out = data_.substr(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return out;
  }
  std::string_view string(const char* field) { return take(u32(field), field); }
  std::string_view bytes64(const char* field) { return take(u64(field), field); }
  std::string_view rest() { return take(remaining(), "data"); }

  // A Map<string, string>: a u32 byte length, then length-prefixed key and value strings.
  std::map<std::string, std::string> string_map(const char* field) {
    RecordCursor entries(take(u32(field), field), file_, where_);
    std::map<std::string, std::string> out;
    while (entries.remaining() > 0) {
      std::string key(entries.string(field));
      out[std::move(key)] = std::string(entries.string(field));
    }
    return out;
  }

  std::size_t remaining() const { return data_.size() - pos_; }
  const std::string& where() const { return where_; }

  [[noreturn]] void fail(const std::string& problem) const { throw ReadError(file_, where_, problem); }

private:
  template <typename T>
  T load(const char* field) {
    const std::string_view raw = take(sizeof(T), field);
    T value;
    std::memcpy(&value, raw.data(), sizeof(T));
    return value;
  }

  std::string_view data_;
  std::size_t pos_ = 0;
  const std::string& file_;
  std::string where_;
};

}  // namespace cloudshape::io::detail::mcap
