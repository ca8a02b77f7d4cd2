// CRC-32 (the zlib / ISO-HDLC polynomial MCAP uses), incrementally over pieces of a buffer.
// zlib takes lengths as uInt: pieces beyond 4 GiB go through in slices.
#include "io/detail/crc32.hpp"

#include <zlib.h>

#include <algorithm>

namespace cloudshape::io::detail {

void Crc32::update(std::string_view bytes) {
  constexpr std::size_t kSlice = 1u << 30;
  while (!bytes.empty()) {
    const std::size_t n = std::min(bytes.size(), kSlice);
    value_ = static_cast<std::uint32_t>(
        ::crc32(value_, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(n)));
    bytes.remove_prefix(n);
  }
}

void Crc32::append(std::uint32_t crc_of_bytes, std::uint64_t length) {
  // zlib's z_off_t is 64 bits wide where a buffer can be this large.
  static_assert(sizeof(z_off_t) >= sizeof(std::size_t), "crc32_combine's length must hold a buffer's size");
  value_ = static_cast<std::uint32_t>(::crc32_combine(value_, crc_of_bytes, static_cast<z_off_t>(length)));
}

}  // namespace cloudshape::io::detail
