// Chunk compression for MCAP: LZ4 frames and Zstandard frames, through Debian's liblz4 and libzstd.
// Decompression never writes beyond the size the chunk declares and reports instead of throwing.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "io/mcap_records.hpp"

namespace cloudshape::io::detail::mcap {

std::string compress(McapCompression compression, std::string_view data);

// Fills `out` with exactly `size` bytes decoded from `in` ("lz4" or "zstd"; an uncompressed
// chunk needs no copy and does not come here). Returns "" on success, else what was wrong.
std::string decompress(std::string_view compression, std::string_view in, std::size_t size, std::string& out);

}  // namespace cloudshape::io::detail::mcap
