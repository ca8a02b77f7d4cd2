// Reads an MCAP recording (mcap.dev/spec) and hands every message, in file order, to a visitor.
// Chunks may be uncompressed, lz4 or zstd; every CRC present is checked; bad input is a ReadError.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "io/cloud_file.hpp"
#include "io/mcap_records.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io {

// `schema` is nullptr for a channel without one (schema id 0).
using McapVisitor =
    std::function<void(const McapChannel& channel, const McapSchema* schema, const McapMessage& message)>;

// What the reader found besides the messages.
struct McapReadSummary {
  std::string profile;  // the Header's, e.g. "ros2"
  std::string library;
  std::uint64_t messages = 0;
  std::uint64_t chunks = 0;
  bool data_crc_checked = false;     // DataEnd held a CRC and it matched
  bool summary_present = false;      // the Footer points at a summary section, read and valid
  bool summary_crc_checked = false;  // ... and the Footer held its CRC, which matched
};

// Messages are visited as they are read: a ReadError thrown later (a truncated tail, a bad
// CRC further on) leaves every message visited before it delivered. `limits.max_bytes` bounds
// the file and each chunk's uncompressed size. The visitor may throw to stop early.
McapReadSummary read_mcap_buffer(std::string_view bytes, const std::string& name, const McapVisitor& visit,
                                 const ReadLimits& limits = {});
// Maps the file into memory (a 2 GB recording is not copied).
McapReadSummary read_mcap_file(const std::string& path, const McapVisitor& visit, const ReadLimits& limits = {});

}  // namespace cloudshape::io
