// The summary's chunk indexes and the message indexes they point at, loaded and cross-checked
// against the records they name, so a reader can start mid-file without reading what precedes.
#include "io/detail/mcap_index.hpp"

#include <algorithm>
#include <cstring>

#include "io/detail/crc32.hpp"
#include "io/detail/mcap_cursor.hpp"
#include "io/detail/mcap_definitions.hpp"
#include "io/detail/mcap_format.hpp"

namespace cloudshape::io::detail::mcap {
namespace {

// Why the index cannot be used; caught by load_index.
struct Unusable {
  std::string why;
};

struct Raw {
  std::uint8_t opcode = 0;
  std::uint64_t offset = 0;
  std::string_view content;
  std::uint64_t end() const { return offset + kRecordPrefix + content.size(); }
};

std::string at(std::uint64_t byte) { return "byte " + std::to_string(byte); }

class Loader {
public:
  explicit Loader(std::string_view bytes) : bytes_(bytes) {}

  McapIndex load() {
    const std::uint64_t footer_at = find_footer();
    RecordCursor footer(record(footer_at, bytes_.size() - kMagic.size(), kFooter, "the Footer").content, name_,
                        "the Footer");
    const std::uint64_t summary_start = footer.u64("summary_start");
    footer.u64("summary_offset_start");
    const std::uint32_t summary_crc = footer.u32("summary_crc");
    if (summary_start == 0) throw Unusable{"the file has no summary section"};
    if (summary_start < kMagic.size() || summary_start > footer_at) {
      throw Unusable{"the Footer's summary_start " + std::to_string(summary_start) + " lies outside the file"};
    }
    summary_start_ = summary_start;
    // Covers the summary, the summary offsets and the Footer up to its CRC field.
    const std::uint64_t covered_end = footer_at + kRecordPrefix + 16;
    if (summary_crc != 0 && crc32_of(bytes_.substr(summary_start, covered_end - summary_start)) != summary_crc) {
      throw Unusable{"the summary CRC does not match"};
    }
    for (std::uint64_t pos = summary_start; pos < footer_at;) {
      const Raw r = record(pos, footer_at, 0, "a summary record");
      summary_record(r);
      pos = r.end();
    }
    if (chunks_.empty()) throw Unusable{"the summary has no chunk index"};
    if (!statistics_) throw Unusable{"the summary has no Statistics record"};
    std::sort(chunks_.begin(), chunks_.end(),
              [](const Pending& a, const Pending& b) { return a.chunk.offset < b.chunk.offset; });
    std::uint64_t counted = 0;
    std::uint64_t previous_end = kMagic.size();
    for (Pending& p : chunks_) {
      check_chunk(p, previous_end);
      previous_end = p.chunk.indexes_end;
      for (const auto& [channel, n] : p.chunk.counts) counted += n;
      index_.chunks.push_back(std::move(p.chunk));
    }
    if (counted != message_count_) {
      throw Unusable{"the message indexes count " + std::to_string(counted) + " messages, the Statistics " +
                     std::to_string(message_count_) + " (messages outside chunks?)"};
    }
    return std::move(index_);
  }

private:
  struct Pending {
    IndexedChunk chunk;
    std::uint64_t where = 0;  // of the ChunkIndex record
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    std::uint64_t index_length = 0;
  };

  std::uint64_t find_footer() const {
    const std::size_t tail = kRecordPrefix + kFooterContent + kMagic.size();
    if (bytes_.size() < kMagic.size() + tail || bytes_.substr(bytes_.size() - kMagic.size()) != kMagic) {
      throw Unusable{"the file does not end with a Footer and the MCAP magic"};
    }
    return bytes_.size() - tail;
  }

  // The record at `pos`, which must end by `end` (and have `opcode` unless it is 0).
  Raw record(std::uint64_t pos, std::uint64_t end, std::uint8_t opcode, const std::string& what) const {
    if (pos > end || end - pos < kRecordPrefix) {
      throw Unusable{what + " at " + at(pos) + " does not fit before " + at(end)};
    }
    Raw r;
    r.opcode = static_cast<std::uint8_t>(bytes_[pos]);
    r.offset = pos;
    std::uint64_t length = 0;
    std::memcpy(&length, bytes_.data() + pos + 1, sizeof length);
    if (length > end - pos - kRecordPrefix) {
      throw Unusable{what + " at " + at(pos) + " declares " + std::to_string(length) + " bytes, past " + at(end)};
    }
    if (opcode != 0 && r.opcode != opcode) {
      throw Unusable{what + " at " + at(pos) + " is a " + opcode_name(r.opcode) + " record, not a " +
                     opcode_name(opcode)};
    }
    r.content = bytes_.substr(pos + kRecordPrefix, length);
    return r;
  }

  void summary_record(const Raw& r) {
    RecordCursor c(r.content, name_, opcode_name(r.opcode) + " record at " + at(r.offset));
    switch (r.opcode) {
      case kSchema: {
        McapSchema s = read_schema_fields(c);
        if (s.id != 0) index_.schemas[s.id] = std::move(s);
        return;
      }
      case kChannel: {
        McapChannel ch = read_channel_fields(c);
        index_.channels[ch.id] = std::move(ch);
        return;
      }
      case kStatistics:
        message_count_ = c.u64("message_count");
        c.u16("schema_count");
        c.u32("channel_count");
        c.u32("attachment_count");
        c.u32("metadata_count");
        c.u32("chunk_count");
        index_.message_start_time = c.u64("message_start_time");
        statistics_ = true;
        return;
      case kChunkIndex: {
        Pending p;
        p.where = r.offset;
        p.chunk.start_time = c.u64("message_start_time");
        p.chunk.end_time = c.u64("message_end_time");
        p.chunk.offset = c.u64("chunk_start_offset");
        p.chunk.length = c.u64("chunk_length");
        RecordCursor offsets(c.string("message_index_offsets"), name_, c.where());
        while (offsets.remaining() > 0) {
          const std::uint16_t channel = offsets.u16("message_index_offsets");
          p.index_offsets[channel] = offsets.u64("message_index_offsets");
        }
        p.index_length = c.u64("message_index_length");
        chunks_.push_back(std::move(p));
        return;
      }
      default: return;
    }
  }

  // The Chunk record and the MessageIndex records a ChunkIndex names, checked against it.
  void check_chunk(Pending& p, std::uint64_t previous_end) const {
    IndexedChunk& chunk = p.chunk;
    const std::string index = "the ChunkIndex record at " + at(p.where);
    if (chunk.offset < previous_end || chunk.length > summary_start_ || chunk.offset > summary_start_ - chunk.length) {
      throw Unusable{index + " points at bytes " + std::to_string(chunk.offset) + "+" + std::to_string(chunk.length) +
                     ", outside the data section or over another chunk"};
    }
    const Raw r = record(chunk.offset, summary_start_, kChunk, index + "'s chunk");
    if (r.end() != chunk.offset + chunk.length) {
      throw Unusable{index + " says the chunk is " + std::to_string(chunk.length) + " bytes, the Chunk record at " +
                     at(chunk.offset) + " is " + std::to_string(r.end() - chunk.offset)};
    }
    RecordCursor c(r.content, name_, "Chunk record at " + at(chunk.offset));
    if (c.u64("message_start_time") != chunk.start_time || c.u64("message_end_time") != chunk.end_time) {
      throw Unusable{index + "'s log times differ from those of the Chunk record at " + at(chunk.offset)};
    }
    const std::uint64_t begin = r.end();
    if (p.index_length > summary_start_ - begin) {
      throw Unusable{index + "'s message_index_length runs past the data section"};
    }
    const std::uint64_t end = begin + p.index_length;
    if (p.index_offsets.empty()) throw Unusable{index + " lists no message index for its chunk"};
    for (const auto& [channel, offset] : p.index_offsets) {
      if (offset < begin) throw Unusable{index + " puts a message index before the end of its chunk"};
      const Raw m = record(offset, end, kMessageIndex, index + "'s message index for channel " + std::to_string(channel));
      RecordCursor mc(m.content, name_, "MessageIndex record at " + at(offset));
      const std::uint16_t on = mc.u16("channel_id");
      const std::uint32_t entries = mc.u32("records");
      if (on != channel || entries % 16 != 0 || entries > mc.remaining()) {
        throw Unusable{"the MessageIndex record at " + at(offset) + " is not the index of channel " +
                       std::to_string(channel) + " that " + index + " says it is"};
      }
      if (index_.channels.count(channel) == 0) {
        throw Unusable{"the MessageIndex record at " + at(offset) + " names channel " + std::to_string(channel) +
                       ", which the summary does not define"};
      }
      chunk.counts[channel] = entries / 16;
    }
    chunk.indexes_end = end;
  }

  std::string_view bytes_;
  const std::string name_;
  std::uint64_t summary_start_ = 0;
  std::vector<Pending> chunks_;
  bool statistics_ = false;
  std::uint64_t message_count_ = 0;
  McapIndex index_;
};

}  // namespace

McapIndex load_index(std::string_view bytes, std::string& problem) {
  problem.clear();
  try {
    return Loader(bytes).load();
  } catch (const Unusable& u) {
    problem = u.why;
  } catch (const ReadError& e) {
    problem = "the " + e.place() + ": " + e.problem();
  }
  return {};
}

}  // namespace cloudshape::io::detail::mcap
