// CRC-32 (the zlib / ISO-HDLC polynomial MCAP uses), incrementally over pieces of a buffer.
// Thin over zlib so the hot loop is zlib's tuned one.
#pragma once

#include <cstdint>
#include <string_view>

namespace cloudshape::io::detail {

class Crc32 {
public:
  void update(std::string_view bytes);
  // As update() over `length` bytes whose own CRC is `crc_of_bytes`, without reading them again.
  void append(std::uint32_t crc_of_bytes, std::uint64_t length);
  std::uint32_t value() const { return value_; }

private:
  std::uint32_t value_ = 0;
};

inline std::uint32_t crc32_of(std::string_view bytes) {
  Crc32 crc;
  crc.update(bytes);
  return crc.value();
}

}  // namespace cloudshape::io::detail
