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

}  // namespace cloudshape::io::detail
