// The summary's chunk indexes and the message indexes they point at, loaded and cross-checked
// against the records they name, so a reader can start mid-file without reading what precedes.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "io/mcap_records.hpp"

namespace cloudshape::io::detail::mcap {

struct IndexedChunk {
  std::uint64_t start_time = 0, end_time = 0;  // log times of its messages
  std::uint64_t offset = 0, length = 0;        // the Chunk record in the file
  std::uint64_t indexes_end = 0;               // the end of its MessageIndex records
  std::map<std::uint16_t, std::uint64_t> counts;  // messages per channel, from its message indexes
};

struct McapIndex {
  std::map<std::uint16_t, McapSchema> schemas;
  std::map<std::uint16_t, McapChannel> channels;
  std::vector<IndexedChunk> chunks;  // in file order
  std::uint64_t message_start_time = 0;  // the Statistics' first log time
};

// The index of `bytes` (a whole MCAP file), or why it cannot be used: `problem` is then a short
// text naming the record at fault ("the ChunkIndex record at byte N points at byte M, which is
// not a Chunk record"). Never throws on bad input; checks every offset it follows, that every
// message index belongs to its chunk, and that the indexes count every message the Statistics
// count (a file with messages outside chunks has no usable index).
McapIndex load_index(std::string_view bytes, std::string& problem);

}  // namespace cloudshape::io::detail::mcap
