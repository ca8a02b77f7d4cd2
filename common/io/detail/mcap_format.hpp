// The MCAP container's fixed vocabulary: magic, record opcodes and their names for messages.
// Shared by the reader and the writer so both speak the same specification.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace cloudshape::io::detail::mcap {

inline constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};
// opcode (1 byte) + content length (8 bytes)
inline constexpr std::size_t kRecordPrefix = 9;
// summary_start, summary_offset_start, summary_crc
inline constexpr std::size_t kFooterContent = 8 + 8 + 4;

enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

inline std::string opcode_name(std::uint8_t op) {
  static constexpr const char* kNames[] = {
      "Header",     "Footer",     "Schema",          "Channel",    "Message",
      "Chunk",      "MessageIndex", "ChunkIndex",    "Attachment", "AttachmentIndex",
      "Statistics", "Metadata",   "MetadataIndex",   "SummaryOffset", "DataEnd"};
  if (op >= kHeader && op <= kDataEnd) return kNames[op - 1];
  return "unknown (opcode " + std::to_string(op) + ")";
}

inline const char* compression_name(std::uint8_t c) {
  switch (c) {
    case 1: return "lz4";
    case 2: return "zstd";
    default: return "";
  }
}

}  // namespace cloudshape::io::detail::mcap
