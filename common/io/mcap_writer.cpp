// Writes an MCAP recording (mcap.dev/spec) that players can seek in: chunks (lz4, zstd or none)
// with CRCs, message indexes, and a summary of schemas, channels, statistics and chunk indexes.
#include "io/mcap_writer.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "io/detail/crc32.hpp"
#include "io/detail/mcap_bytes.hpp"
#include "io/detail/mcap_compression.hpp"
#include "io/detail/mcap_format.hpp"

namespace cloudshape::io {
namespace m = detail::mcap;

McapWriter::McapWriter(const std::string& path, McapWriterOptions options)
    : owned_(std::make_unique<std::ofstream>(path, std::ios::binary | std::ios::trunc)),
      out_(owned_.get()),
      name_(path),
      options_(std::move(options)) {
  if (!*owned_) throw std::runtime_error(path + ": cannot create the recording");
  start();
}

McapWriter::McapWriter(std::ostream& out, std::string name, McapWriterOptions options)
    : out_(&out), name_(std::move(name)), options_(std::move(options)) {
  start();
}

McapWriter::~McapWriter() {
  try {
    close();
  } catch (const std::exception&) {
    // Destroyed during unwinding or after a failed write: the caller already has an error.
  }
}

void McapWriter::start() {
  emit(m::kMagic);
  std::string header;
  m::put_string(header, options_.profile);
  m::put_string(header, options_.library);
  emit_record(m::kHeader, header);
}

void McapWriter::emit(std::string_view bytes) {
  out_->write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!*out_) throw std::runtime_error(name_ + ": write failed at byte " + std::to_string(offset_));
  if (!in_summary_) data_crc_.update(bytes);
  offset_ += bytes.size();
}

void McapWriter::emit_record(std::uint8_t opcode, std::string_view content) {
  std::string record;
  record.reserve(m::kRecordPrefix);
  m::put<std::uint8_t>(record, opcode);
  m::put<std::uint64_t>(record, content.size());
  emit(record);
  emit(content);
}

std::uint16_t McapWriter::add_schema(std::string name, std::string encoding, std::string data) {
  const auto id = static_cast<std::uint16_t>(schema_records_.size() + 1);
  std::string content;
  m::put<std::uint16_t>(content, id);
  m::put_string(content, name);
  m::put_string(content, encoding);
  m::put_string(content, data);
  // Straight into the data section, ahead of any chunk that will use it.
  emit_record(m::kSchema, content);
  schema_records_.push_back(std::move(content));
  return id;
}

std::uint16_t McapWriter::add_channel(std::uint16_t schema_id, std::string topic, std::string message_encoding,
                                      std::map<std::string, std::string> metadata) {
  if (schema_id > schema_records_.size()) {
    throw std::invalid_argument(name_ + ": channel " + topic + " names schema " + std::to_string(schema_id) +
                                ", which was not added");
  }
  const auto id = static_cast<std::uint16_t>(channel_records_.size() + 1);
  std::string content;
  m::put<std::uint16_t>(content, id);
  m::put<std::uint16_t>(content, schema_id);
  m::put_string(content, topic);
  m::put_string(content, message_encoding);
  m::put_string_map(content, metadata);
  emit_record(m::kChannel, content);
  channel_records_.push_back(std::move(content));
  return id;
}

void McapWriter::write(std::uint16_t channel_id, std::uint64_t log_time, std::uint64_t publish_time,
                       std::string_view data) {
  if (closed_) throw std::logic_error(name_ + ": write after close");
  if (channel_id == 0 || channel_id > channel_records_.size()) {
    throw std::invalid_argument(name_ + ": message on channel " + std::to_string(channel_id) + ", which was not added");
  }
  std::string content;
  content.reserve(22 + data.size());
  m::put<std::uint16_t>(content, channel_id);
  m::put<std::uint32_t>(content, ++sequences_[channel_id]);
  m::put<std::uint64_t>(content, log_time);
  m::put<std::uint64_t>(content, publish_time);
  content.append(data);

  first_time_ = message_count_ == 0 ? log_time : std::min(first_time_, log_time);
  last_time_ = message_count_ == 0 ? log_time : std::max(last_time_, log_time);
  ++message_count_;
  ++channel_counts_[channel_id];
  if (!options_.chunked) {
    emit_record(m::kMessage, content);
    return;
  }
  if (chunk_.records.empty()) chunk_.start_time = chunk_.end_time = log_time;
  chunk_.start_time = std::min(chunk_.start_time, log_time);
  chunk_.end_time = std::max(chunk_.end_time, log_time);
  chunk_.index[channel_id].emplace_back(log_time, chunk_.records.size());
  m::put_record(chunk_.records, m::kMessage, content);
  if (chunk_.records.size() >= options_.chunk_size) flush_chunk();
}

void McapWriter::flush_chunk() {
  if (chunk_.records.empty()) return;
  const std::string compressed = m::compress(options_.compression, chunk_.records);
  std::string content;
  m::put<std::uint64_t>(content, chunk_.start_time);
  m::put<std::uint64_t>(content, chunk_.end_time);
  m::put<std::uint64_t>(content, chunk_.records.size());
  m::put<std::uint32_t>(content, detail::crc32_of(chunk_.records));
  m::put_string(content, m::compression_name(static_cast<std::uint8_t>(options_.compression)));
  m::put<std::uint64_t>(content, compressed.size());

  ChunkIndexEntry entry{};
  entry.start_time = chunk_.start_time;
  entry.end_time = chunk_.end_time;
  entry.offset = offset_;
  entry.length = m::kRecordPrefix + content.size() + compressed.size();
  entry.compressed_size = compressed.size();
  entry.uncompressed_size = chunk_.records.size();
  // The compressed records are emitted as they are, not copied into the record.
  std::string prefix;
  m::put<std::uint8_t>(prefix, m::kChunk);
  m::put<std::uint64_t>(prefix, content.size() + compressed.size());
  emit(prefix);
  emit(content);
  emit(compressed);

  const std::uint64_t index_start = offset_;
  if (!options_.indexed) chunk_.index.clear();
  for (const auto& [channel, entries] : chunk_.index) {
    std::string index;
    m::put<std::uint16_t>(index, channel);
    m::put<std::uint32_t>(index, static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [time, at] : entries) {
      m::put<std::uint64_t>(index, time);
      m::put<std::uint64_t>(index, at);
    }
    entry.index_offsets[channel] = offset_;
    emit_record(m::kMessageIndex, index);
  }
  entry.index_length = offset_ - index_start;
  chunk_indexes_.push_back(std::move(entry));
  chunk_ = OpenChunk{};
}

void McapWriter::close() {
  if (closed_) return;
  closed_ = true;
  flush_chunk();
  std::string data_end;
  m::put<std::uint32_t>(data_end, data_crc_.value());
  emit_record(m::kDataEnd, data_end);
  write_summary();
  out_->flush();
  if (!*out_) throw std::runtime_error(name_ + ": write failed while closing the recording");
  if (owned_) owned_->close();
}

void McapWriter::write_summary() {
  in_summary_ = true;
  const std::uint64_t summary_start = offset_;
  std::string summary;
  struct Group {
    std::uint8_t opcode;
    std::uint64_t start, length;
  };
  std::vector<Group> groups;
  const auto group = [&](std::uint8_t opcode, const std::vector<std::string>& contents) {
    if (contents.empty()) return;
    const std::uint64_t start = summary_start + summary.size();
    for (const std::string& c : contents) m::put_record(summary, opcode, c);
    groups.push_back({opcode, start, summary_start + summary.size() - start});
  };
  group(m::kSchema, schema_records_);
  group(m::kChannel, channel_records_);

  std::string stats;
  m::put<std::uint64_t>(stats, message_count_);
  m::put<std::uint16_t>(stats, static_cast<std::uint16_t>(schema_records_.size()));
  m::put<std::uint32_t>(stats, static_cast<std::uint32_t>(channel_records_.size()));
  m::put<std::uint32_t>(stats, 0);  // attachments
  m::put<std::uint32_t>(stats, 0);  // metadata
  m::put<std::uint32_t>(stats, static_cast<std::uint32_t>(chunk_indexes_.size()));
  m::put<std::uint64_t>(stats, first_time_);
  m::put<std::uint64_t>(stats, last_time_);
  std::string counts;
  for (const auto& [channel, n] : channel_counts_) {
    m::put<std::uint16_t>(counts, channel);
    m::put<std::uint64_t>(counts, n);
  }
  m::put<std::uint32_t>(stats, static_cast<std::uint32_t>(counts.size()));
  stats += counts;
  group(m::kStatistics, {stats});

  std::vector<std::string> indexes;
  for (const ChunkIndexEntry& e : chunk_indexes_) {
    std::string c;
    m::put<std::uint64_t>(c, e.start_time);
    m::put<std::uint64_t>(c, e.end_time);
    m::put<std::uint64_t>(c, e.offset);
    m::put<std::uint64_t>(c, e.length);
    std::string offsets;
    for (const auto& [channel, at] : e.index_offsets) {
      m::put<std::uint16_t>(offsets, channel);
      m::put<std::uint64_t>(offsets, at);
    }
    m::put<std::uint32_t>(c, static_cast<std::uint32_t>(offsets.size()));
    c += offsets;
    m::put<std::uint64_t>(c, e.index_length);
    m::put_string(c, m::compression_name(static_cast<std::uint8_t>(options_.compression)));
    m::put<std::uint64_t>(c, e.compressed_size);
    m::put<std::uint64_t>(c, e.uncompressed_size);
    indexes.push_back(std::move(c));
  }
  if (options_.indexed) group(m::kChunkIndex, indexes);

  const std::uint64_t offsets_start = summary_start + summary.size();
  for (const Group& g : groups) {
    std::string c;
    m::put<std::uint8_t>(c, g.opcode);
    m::put<std::uint64_t>(c, g.start);
    m::put<std::uint64_t>(c, g.length);
    m::put_record(summary, m::kSummaryOffset, c);
  }
  std::string footer;
  m::put<std::uint8_t>(footer, m::kFooter);
  m::put<std::uint64_t>(footer, m::kFooterContent);
  m::put<std::uint64_t>(footer, summary_start);
  m::put<std::uint64_t>(footer, offsets_start);
  detail::Crc32 crc;
  crc.update(summary);
  crc.update(footer);
  m::put<std::uint32_t>(footer, crc.value());
  emit(summary);
  emit(footer);
  emit(m::kMagic);
}

}  // namespace cloudshape::io
