// Reads an MCAP recording (mcap.dev/spec) and hands every message, in file order, to a visitor.
// One pass front to back: data section, then the summary the Footer points at, then the magic.
#include "io/mcap_reader.hpp"

#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <utility>

#include "io/detail/crc32.hpp"
#include "io/detail/input.hpp"
#include "io/detail/mapped_file.hpp"
#include "io/detail/mcap_compression.hpp"
#include "io/detail/mcap_cursor.hpp"
#include "io/detail/mcap_definitions.hpp"
#include "io/detail/mcap_format.hpp"
#include "io/detail/mcap_index.hpp"

namespace cloudshape::io {
namespace {
namespace m = detail::mcap;

std::string hex(std::uint32_t v) {
  char text[11];
  std::snprintf(text, sizeof text, "0x%08x", v);
  return text;
}

struct Record {
  std::uint8_t opcode = 0;
  std::size_t offset = 0;  // of the opcode, within the buffer being walked
  std::string_view content;
  std::size_t end() const { return offset + m::kRecordPrefix + content.size(); }
};

class Reader {
public:
  Reader(std::string_view bytes, const std::string& name, const McapVisitor& visit, const ReadLimits& limits,
         const McapStart* start = nullptr)
      : bytes_(bytes), name_(name), visit_(visit), limits_(limits), start_(start) {
    reached_ = start_ == nullptr || start_->message == 0;
  }

  McapReadSummary run() {
    detail::check_buffer(bytes_, name_, limits_);
    if (bytes_.size() < m::kMagic.size() || bytes_.substr(0, m::kMagic.size()) != m::kMagic) {
      throw ReadError(name_, detail::at_byte(0), "not an MCAP file: it does not start with the MCAP magic");
    }
    std::size_t pos = m::kMagic.size();
    const Record header = next_record(pos, "file");
    if (header.opcode != m::kHeader) {
      throw ReadError(name_, where(header),
                      "the first record is " + m::opcode_name(header.opcode) + ", an MCAP file starts with a Header");
    }
    read_header(header);
    pos = header.end();
    if (start_ != nullptr) pos = seek(pos);
    pos = read_data_section(pos);
    read_summary_and_footer(pos);
    return summary_;
  }

private:
  std::string where(const Record& r, std::size_t chunk_offset = kNoChunk) const {
    std::string place = m::opcode_name(r.opcode) + " record at byte " + std::to_string(r.offset);
    if (chunk_offset != kNoChunk) place += " of the Chunk at byte " + std::to_string(chunk_offset);
    return place;
  }

  // The record starting at `pos` of `buffer` (the file, or a chunk's records).
  Record next_record(std::size_t pos, const char* buffer_name, std::string_view buffer = {},
                     std::size_t chunk_offset = kNoChunk) const {
    if (buffer.data() == nullptr) buffer = bytes_;
    const std::string place = chunk_offset == kNoChunk ? detail::at_byte(pos)
                                                       : "byte " + std::to_string(pos) + " of the Chunk at byte " +
                                                             std::to_string(chunk_offset);
    const std::size_t left = buffer.size() - pos;
    if (left < m::kRecordPrefix) {
      throw ReadError(name_, place,
                      std::string("truncated: a record needs a 9-byte opcode and length, the ") + buffer_name +
                          " has " + std::to_string(left) + " bytes left");
    }
    Record r;
    r.opcode = static_cast<std::uint8_t>(buffer[pos]);
    r.offset = pos;
    std::uint64_t length = 0;
    std::memcpy(&length, buffer.data() + pos + 1, sizeof length);
    if (length > left - m::kRecordPrefix) {
      throw ReadError(name_, where(r, chunk_offset),
                      "truncated or bad length: the record declares " + std::to_string(length) +
                          " bytes, the " + buffer_name + " has " + std::to_string(left - m::kRecordPrefix) +
                          " left");
    }
    r.content = buffer.substr(pos + m::kRecordPrefix, static_cast<std::size_t>(length));
    return r;
  }

  bool counted(const McapChannel& channel, const McapSchema* schema) const {
    return !start_->counted || start_->counted(channel, schema);
  }

  // Through the index, past the chunks wholly before the start: where reading goes on.
  std::size_t seek(std::size_t pos) {
    std::string problem;
    detail::mcap::McapIndex index = detail::mcap::load_index(bytes_, problem);
    if (!problem.empty()) {
      summary_.index_problem = problem;
      if (start_->unindexed) start_->unindexed(problem);
      return pos;
    }
    summary_.index_used = true;
    schemas_ = std::move(index.schemas);
    channels_ = std::move(index.channels);
    first_log_time_ = index.message_start_time;
    std::uint64_t passed = 0;
    for (const detail::mcap::IndexedChunk& chunk : index.chunks) {
      std::uint64_t in_chunk = 0;
      for (const auto& [id, n] : chunk.counts) {
        const McapChannel& channel = channels_.at(id);
        const auto schema = schemas_.find(channel.schema_id);
        if (counted(channel, schema == schemas_.end() ? nullptr : &schema->second)) in_chunk += n;
      }
      const bool before_message = start_->message > 0 && counted_ + in_chunk <= start_->message;
      const bool before_time = start_->after_ns > 0 && chunk.end_time < *first_log_time_ + start_->after_ns;
      if (!before_message && !before_time) {
        pos = static_cast<std::size_t>(chunk.offset);
        break;
      }
      counted_ += in_chunk;
      passed += in_chunk;
      ++summary_.chunks_skipped;
      pos = static_cast<std::size_t>(chunk.indexes_end);
    }
    if (passed > 0 && start_->skipped) start_->skipped(passed);
    return pos;
  }

  // Whether a message comes before the start (and is passed over).
  bool before_start(const McapChannel& channel, const McapSchema* schema, const McapMessage& msg) {
    if (start_ == nullptr) return false;
    const bool is_counted = counted(channel, schema);
    bool before = false;
    if (!reached_) {
      if (is_counted && counted_ >= start_->message) reached_ = true;
      else before = true;
    }
    if (is_counted) ++counted_;
    if (!first_log_time_) first_log_time_ = msg.log_time;
    if (start_->after_ns > 0 && msg.log_time < *first_log_time_ + start_->after_ns) before = true;
    if (before && is_counted && start_->skipped) start_->skipped(1);
    return before;
  }

  void read_header(const Record& r) {
    m::RecordCursor c(r.content, name_, where(r));
    summary_.profile = std::string(c.string("profile"));
    summary_.library = std::string(c.string("library"));
  }

  // The data section's CRC is taken record by record as the walk passes them, so that an
  // uncompressed chunk's records, which their own CRC covers too, are read for it only once.
  // After a seek that skipped chunks it is not checked, and not taken.
  std::size_t read_data_section(std::size_t pos) {
    const bool hashing = summary_.chunks_skipped == 0;
    if (hashing) data_crc_.update(bytes_.substr(0, pos));
    for (;;) {
      if (pos == bytes_.size()) {
        throw ReadError(name_, detail::at_byte(pos),
                        "truncated: the file ends without a DataEnd or Footer record (an interrupted recording?)");
      }
      const Record r = next_record(pos, "file");
      switch (r.opcode) {
        case m::kDataEnd: {
          // Chunks skipped unread: the bytes the CRC covers were not all read, and are not now.
          if (!hashing) return r.end();
          check_data_end(r);
          return r.end();
        }
        case m::kFooter: return pos;  // a writer that skipped DataEnd: accepted, nothing to check
        case m::kHeader: throw ReadError(name_, where(r), "a second Header record");
        case m::kChunk: read_chunk(r, hashing); break;
        default:
          read_plain_record(r, kNoChunk);
          if (hashing) data_crc_.update(bytes_.substr(r.offset, r.end() - r.offset));
          break;
      }
      pos = r.end();
    }
  }

  void check_data_end(const Record& r) {
    m::RecordCursor c(r.content, name_, where(r));
    const std::uint32_t stored = c.u32("data_section_crc");
    if (stored == 0) return;
    if (stored != data_crc_.value()) {
      throw ReadError(name_, where(r),
                      "data section CRC mismatch: the file says " + hex(stored) + ", the bytes give " +
                          hex(data_crc_.value()));
    }
    summary_.data_crc_checked = true;
  }

  // Schema, Channel, Message and the records a reader may skip, in the data section or a chunk.
  void read_plain_record(const Record& r, std::size_t chunk_offset) {
    switch (r.opcode) {
      case m::kSchema: read_schema(r, chunk_offset); return;
      case m::kChannel: read_channel(r, chunk_offset); return;
      case m::kMessage: read_message(r, chunk_offset); return;
      case m::kAttachment:
        if (chunk_offset == kNoChunk) check_attachment(r);
        else break;
        return;
      case m::kMessageIndex:
      case m::kMetadata:
        if (chunk_offset == kNoChunk) return;
        break;
      case m::kHeader:
      case m::kFooter:
      case m::kChunk:
      case m::kChunkIndex:
      case m::kAttachmentIndex:
      case m::kStatistics:
      case m::kMetadataIndex:
      case m::kSummaryOffset:
      case m::kDataEnd: break;
      default: return;  // unknown opcodes (private records among them) are skipped, as the spec asks
    }
    throw ReadError(name_, where(r, chunk_offset),
                    chunk_offset == kNoChunk ? "this record does not belong in the data section"
                                             : "a Chunk holds only Schema, Channel and Message records");
  }

  McapSchema parse_schema(const Record& r, std::size_t chunk_offset) const {
    m::RecordCursor c(r.content, name_, where(r, chunk_offset));
    return m::read_schema_fields(c);
  }

  void read_schema(const Record& r, std::size_t chunk_offset) {
    McapSchema s = parse_schema(r, chunk_offset);
    if (s.id == 0) return;  // id 0 means "no schema": such a record is to be ignored
    const auto [it, inserted] = schemas_.emplace(s.id, s);
    if (!inserted && (it->second.name != s.name || it->second.encoding != s.encoding || it->second.data != s.data)) {
      throw ReadError(name_, where(r, chunk_offset),
                      "schema " + std::to_string(s.id) + " redefined with different contents");
    }
  }

  McapChannel parse_channel(const Record& r, std::size_t chunk_offset) const {
    m::RecordCursor c(r.content, name_, where(r, chunk_offset));
    return m::read_channel_fields(c);
  }

  void read_channel(const Record& r, std::size_t chunk_offset) {
    McapChannel ch = parse_channel(r, chunk_offset);
    if (ch.schema_id != 0 && schemas_.count(ch.schema_id) == 0) {
      throw ReadError(name_, where(r, chunk_offset),
                      "channel " + std::to_string(ch.id) + " names schema " + std::to_string(ch.schema_id) +
                          ", which no earlier Schema record defines");
    }
    const auto [it, inserted] = channels_.emplace(ch.id, ch);
    if (!inserted && (it->second.schema_id != ch.schema_id || it->second.topic != ch.topic ||
                      it->second.message_encoding != ch.message_encoding || it->second.metadata != ch.metadata)) {
      throw ReadError(name_, where(r, chunk_offset),
                      "channel " + std::to_string(ch.id) + " redefined with different contents");
    }
  }

  void read_message(const Record& r, std::size_t chunk_offset) {
    m::RecordCursor c(r.content, name_, where(r, chunk_offset));
    McapMessage msg;
    msg.channel_id = c.u16("channel_id");
    msg.sequence = c.u32("sequence");
    msg.log_time = c.u64("log_time");
    msg.publish_time = c.u64("publish_time");
    msg.data = c.rest();
    const auto channel = channels_.find(msg.channel_id);
    if (channel == channels_.end()) {
      throw ReadError(name_, where(r, chunk_offset),
                      "message on channel " + std::to_string(msg.channel_id) +
                          ", which no earlier Channel record defines");
    }
    const McapSchema* schema = nullptr;
    if (channel->second.schema_id != 0) schema = &schemas_.at(channel->second.schema_id);
    if (before_start(channel->second, schema, msg)) return;
    ++summary_.messages;
    visit_(channel->second, schema, msg);
  }

  void check_attachment(const Record& r) {
    m::RecordCursor c(r.content, name_, where(r));
    c.u64("log_time");
    c.u64("create_time");
    c.string("name");
    c.string("media_type");
    c.bytes64("data");
    const std::size_t covered = r.content.size() - c.remaining();
    const std::uint32_t stored = c.u32("crc");
    if (stored != 0 && stored != detail::crc32_of(r.content.substr(0, covered))) {
      throw ReadError(name_, where(r), "attachment CRC mismatch: the file says " + hex(stored) + ", the bytes give " +
                                           hex(detail::crc32_of(r.content.substr(0, covered))));
    }
  }

  // `hashing`: the chunk's bytes go into the data section's CRC too.
  void read_chunk(const Record& r, bool hashing) {
    m::RecordCursor c(r.content, name_, where(r));
    c.u64("message_start_time");
    c.u64("message_end_time");
    const std::uint64_t size = c.u64("uncompressed_size");
    const std::uint32_t stored_crc = c.u32("uncompressed_crc");
    const std::string_view compression = c.string("compression");
    const std::string_view data = c.bytes64("records");
    if (size > limits_.max_bytes) {
      throw ReadError(name_, where(r),
                      "the chunk declares " + std::to_string(size) + " uncompressed bytes, more than the limit of " +
                          std::to_string(limits_.max_bytes));
    }
    std::string_view records = data;
    if (!compression.empty()) {
      const std::string problem = m::decompress(compression, data, static_cast<std::size_t>(size), chunk_buffer_);
      if (!problem.empty()) throw ReadError(name_, where(r), problem);
      records = chunk_buffer_;
    } else if (data.size() != size) {
      throw ReadError(name_, where(r),
                      "uncompressed chunk holds " + std::to_string(data.size()) + " bytes, it declares " +
                          std::to_string(size));
    }
    const std::string_view whole = bytes_.substr(r.offset, r.end() - r.offset);
    if (stored_crc != 0) {
      const std::uint32_t crc = detail::crc32_of(records);
      if (crc != stored_crc) {
        throw ReadError(name_, where(r),
                        "chunk CRC mismatch: the file says " + hex(stored_crc) + ", the uncompressed records give " +
                            hex(crc));
      }
      if (hashing && compression.empty()) {
        // The records are the chunk's own bytes here: their CRC joins the data section's.
        const auto before = static_cast<std::size_t>(data.data() - whole.data());
        data_crc_.update(whole.substr(0, before));
        data_crc_.append(crc, data.size());
        data_crc_.update(whole.substr(before + data.size()));
        hashing = false;
      }
    }
    if (hashing) data_crc_.update(whole);
    ++summary_.chunks;
    for (std::size_t pos = 0; pos < records.size();) {
      const Record inner = next_record(pos, "chunk", records, r.offset);
      read_plain_record(inner, r.offset);
      pos = inner.end();
    }
  }

  void read_summary_and_footer(std::size_t pos) {
    const std::size_t summary_begin = pos;
    for (;;) {
      if (pos == bytes_.size()) {
        throw ReadError(name_, detail::at_byte(pos), "truncated: the file ends without a Footer record");
      }
      const Record r = next_record(pos, "file");
      if (r.opcode == m::kFooter) {
        read_footer(r, summary_begin);
        return;
      }
      read_summary_record(r);
      pos = r.end();
    }
  }

  // The summary repeats what the data section defined and indexes it; each record must parse.
  void read_summary_record(const Record& r) {
    m::RecordCursor c(r.content, name_, where(r));
    switch (r.opcode) {
      case m::kSchema: {
        const McapSchema s = parse_schema(r, kNoChunk);
        const auto it = schemas_.find(s.id);
        if (s.id != 0 && it != schemas_.end() && it->second.data != s.data) {
          throw ReadError(name_, where(r), "schema " + std::to_string(s.id) + " differs from the data section's");
        }
        return;
      }
      case m::kChannel: {
        const McapChannel ch = parse_channel(r, kNoChunk);
        const auto it = channels_.find(ch.id);
        if (it != channels_.end() && (it->second.topic != ch.topic || it->second.schema_id != ch.schema_id)) {
          throw ReadError(name_, where(r), "channel " + std::to_string(ch.id) + " differs from the data section's");
        }
        return;
      }
      case m::kChunkIndex: {
        c.u64("message_start_time");
        c.u64("message_end_time");
        const std::uint64_t start = c.u64("chunk_start_offset");
        const std::uint64_t length = c.u64("chunk_length");
        if (start > bytes_.size() || length > bytes_.size() - start) {
          throw ReadError(name_, where(r),
                          "the chunk index points at bytes " + std::to_string(start) + "+" + std::to_string(length) +
                              ", beyond the file's " + std::to_string(bytes_.size()));
        }
        c.take(c.u32("message_index_offsets"), "message_index_offsets");
        c.u64("message_index_length");
        c.string("compression");
        c.u64("compressed_size");
        c.u64("uncompressed_size");
        return;
      }
      case m::kStatistics: {
        c.u64("message_count");
        c.u16("schema_count");
        c.u32("channel_count");
        c.u32("attachment_count");
        c.u32("metadata_count");
        c.u32("chunk_count");
        c.u64("message_start_time");
        c.u64("message_end_time");
        c.take(c.u32("channel_message_counts"), "channel_message_counts");
        return;
      }
      case m::kSummaryOffset: {
        c.u8("group_opcode");
        const std::uint64_t start = c.u64("group_start");
        const std::uint64_t length = c.u64("group_length");
        if (start > bytes_.size() || length > bytes_.size() - start) {
          throw ReadError(name_, where(r), "the summary offset points beyond the end of the file");
        }
        return;
      }
      case m::kAttachmentIndex:
      case m::kMetadataIndex:
      case m::kMetadata: return;
      case m::kHeader:
      case m::kMessage:
      case m::kChunk:
      case m::kMessageIndex:
      case m::kAttachment:
      case m::kDataEnd:
        throw ReadError(name_, where(r), "this record does not belong in the summary section");
      default: return;
    }
  }

  void read_footer(const Record& r, std::size_t summary_begin) {
    m::RecordCursor c(r.content, name_, where(r));
    const std::uint64_t summary_start = c.u64("summary_start");
    const std::uint64_t summary_offset_start = c.u64("summary_offset_start");
    const std::uint32_t summary_crc = c.u32("summary_crc");
    const std::size_t end = r.end();
    if (bytes_.size() - end != m::kMagic.size() || bytes_.substr(end) != m::kMagic) {
      throw ReadError(name_, detail::at_byte(end),
                      bytes_.size() - end < m::kMagic.size()
                          ? "truncated: the closing MCAP magic is missing"
                          : "the file does not end with the MCAP magic right after the Footer");
    }
    if (summary_start == 0) return;
    if (summary_start != summary_begin || summary_offset_start > r.offset ||
        (summary_offset_start != 0 && summary_offset_start < summary_start)) {
      throw ReadError(name_, where(r),
                      "the Footer's summary_start " + std::to_string(summary_start) + " or summary_offset_start " +
                          std::to_string(summary_offset_start) + " does not match the summary at byte " +
                          std::to_string(summary_begin));
    }
    summary_.summary_present = true;
    if (summary_crc == 0) return;
    // Covers the summary, the summary offsets and the Footer up to its CRC field.
    const std::size_t covered_end = r.offset + m::kRecordPrefix + 16;
    const std::uint32_t crc =
        detail::crc32_of(bytes_.substr(static_cast<std::size_t>(summary_start), covered_end - summary_start));
    if (crc != summary_crc) {
      throw ReadError(name_, where(r),
                      "summary CRC mismatch: the file says " + hex(summary_crc) + ", the bytes give " + hex(crc));
    }
    summary_.summary_crc_checked = true;
  }

  static constexpr std::size_t kNoChunk = static_cast<std::size_t>(-1);

  std::string_view bytes_;
  const std::string& name_;
  const McapVisitor& visit_;
  const ReadLimits& limits_;
  const McapStart* start_;
  bool reached_ = true;                         // the start's message was reached
  std::uint64_t counted_ = 0;                   // counted messages so far, read or skipped
  std::optional<std::uint64_t> first_log_time_;  // the origin of McapStart::after_ns
  std::map<std::uint16_t, McapSchema> schemas_;
  std::map<std::uint16_t, McapChannel> channels_;
  std::string chunk_buffer_;
  detail::Crc32 data_crc_;
  McapReadSummary summary_;
};

}  // namespace

McapReadSummary read_mcap_buffer(std::string_view bytes, const std::string& name, const McapVisitor& visit,
                                 const ReadLimits& limits) {
  return Reader(bytes, name, visit, limits).run();
}

McapReadSummary read_mcap_file(const std::string& path, const McapVisitor& visit, const ReadLimits& limits) {
  const detail::MappedFile file(path, limits);
  return read_mcap_buffer(file.bytes(), path, visit, limits);
}

}  // namespace cloudshape::io

namespace cloudshape::io {

McapReadSummary read_mcap_buffer_from(std::string_view bytes, const std::string& name, const McapStart& start,
                                      const McapVisitor& visit, const ReadLimits& limits) {
  return Reader(bytes, name, visit, limits, &start).run();
}

McapReadSummary read_mcap_file_from(const std::string& path, const McapStart& start, const McapVisitor& visit,
                                    const ReadLimits& limits) {
  const detail::MappedFile file(path, limits);
  return read_mcap_buffer_from(file.bytes(), path, start, visit, limits);
}

}  // namespace cloudshape::io
