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
  // Reads with a McapStart only:
  bool index_used = false;          // the summary's indexes were checked and used to seek
  std::string index_problem;        // else why not ("the file has no summary section", ...)
  std::uint64_t chunks_skipped = 0; // chunks passed over unread
};

// Where a read starts: messages before it are not visited. With a usable index (the summary's
// chunk indexes and the message indexes they point at, each checked against the records it
// names first) the chunks before it are not even read; otherwise (no summary, no index, an
// index that lies) the file is read from its start and the messages before it passed over.
struct McapStart {
  // The first message to visit among those `counted` counts, from 0 (file order).
  std::uint64_t message = 0;
  // Visit only messages logged at least this long after the recording's first log time (the
  // summary's Statistics when the index is used, else the first message's).
  std::uint64_t after_ns = 0;
  // Which messages `message` counts (e.g. the PointCloud2 ones); empty: every message.
  std::function<bool(const McapChannel&, const McapSchema*)> counted;
  // Told how many counted messages were passed over, so a caller's numbering goes on.
  std::function<void(std::uint64_t)> skipped;
  // Told, before reading, why the file has no usable index (then read from its start).
  std::function<void(const std::string& why)> unindexed;
};

// Messages are visited as they are read: a ReadError thrown later (a truncated tail, a bad
// CRC further on) leaves every message visited before it delivered. `limits.max_bytes` bounds
// the file and each chunk's uncompressed size. The visitor may throw to stop early.
McapReadSummary read_mcap_buffer(std::string_view bytes, const std::string& name, const McapVisitor& visit,
                                 const ReadLimits& limits = {});
// Maps the file into memory (a 2 GB recording is not copied).
McapReadSummary read_mcap_file(const std::string& path, const McapVisitor& visit, const ReadLimits& limits = {});

// The same from `start` on; the data section's CRC is not checked when chunks were skipped.
McapReadSummary read_mcap_buffer_from(std::string_view bytes, const std::string& name, const McapStart& start,
                                      const McapVisitor& visit, const ReadLimits& limits = {});
McapReadSummary read_mcap_file_from(const std::string& path, const McapStart& start, const McapVisitor& visit,
                                    const ReadLimits& limits = {});

}  // namespace cloudshape::io
