// Writes an MCAP recording (mcap.dev/spec) that players can seek in: chunks (lz4, zstd or none)
// with CRCs, message indexes, and a summary of schemas, channels, statistics and chunk indexes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "io/detail/crc32.hpp"
#include "io/mcap_records.hpp"

namespace cloudshape::io {

struct McapWriterOptions {
  McapCompression compression = McapCompression::zstd;
  // Off: messages go straight into the data section, unindexed (for tests of such files).
  bool chunked = true;
  // Off: chunks without message indexes and a summary without chunk indexes (as some writers
  // make them: readers must then read from the start).
  bool indexed = true;
  // A chunk is closed once its uncompressed records reach this size: a player decodes one
  // chunk to seek, so a chunk should hold about a second of a camera's clouds at most.
  std::size_t chunk_size = 4u << 20;
  std::string profile = "ros2";
  std::string library = "cloudshape";
};

// Throws std::runtime_error naming the file when writing fails. close() completes the file;
// a writer destroyed without it still closes, ignoring errors (an exception is unwinding).
class McapWriter {
public:
  McapWriter(const std::string& path, McapWriterOptions options = {});
  // Writes to `out`, which must outlive the writer; `name` is for error messages.
  McapWriter(std::ostream& out, std::string name, McapWriterOptions options = {});
  ~McapWriter();
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  std::uint16_t add_schema(std::string name, std::string encoding, std::string data);
  std::uint16_t add_channel(std::uint16_t schema_id, std::string topic, std::string message_encoding,
                            std::map<std::string, std::string> metadata = {});
  // The Message record's sequence field counts the channel's messages from 1.
  void write(std::uint16_t channel_id, std::uint64_t log_time, std::uint64_t publish_time, std::string_view data);
  void close();

private:
  struct ChunkIndexEntry {
    std::uint64_t start_time, end_time, offset, length, compressed_size, uncompressed_size;
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    std::uint64_t index_length;
  };
  struct OpenChunk {
    std::string records;
    std::uint64_t start_time = 0, end_time = 0;
    std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> index;  // time, offset
  };

  void start();
  void emit(std::string_view bytes);
  void emit_record(std::uint8_t opcode, std::string_view content);
  void flush_chunk();
  void write_summary();

  std::unique_ptr<std::ofstream> owned_;
  std::ostream* out_;
  std::string name_;
  McapWriterOptions options_;
  bool closed_ = false;
  std::uint64_t offset_ = 0;
  detail::Crc32 data_crc_;  // of everything before DataEnd
  bool in_summary_ = false;
  std::vector<std::string> schema_records_, channel_records_;
  std::map<std::uint16_t, std::uint32_t> sequences_;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;
  std::uint64_t message_count_ = 0, first_time_ = 0, last_time_ = 0;
  OpenChunk chunk_;
  std::vector<ChunkIndexEntry> chunk_indexes_;
};

}  // namespace cloudshape::io
