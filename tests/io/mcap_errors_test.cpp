// MCAP reader on damaged input: every failure is one ReadError naming the file, the record
// (its byte offset) and the problem; never a crash or a hang; messages read before it stay read.
#include <gtest/gtest.h>

#include "io/detail/crc32.hpp"
#include "io/detail/mcap_bytes.hpp"
#include "io/detail/mcap_format.hpp"
#include "io_test_support.hpp"
#include "mcap_test_support.hpp"

namespace cloudshape::io {
namespace {
namespace m = detail::mcap;
using test::expect_read_error;
using test::first_of;
using test::poke;
using test::read_all;
using test::small_recording;
using test::top_records;

std::string recording(McapCompression compression = McapCompression::zstd, bool chunked = true) {
  McapWriterOptions options;
  options.compression = compression;
  options.chunked = chunked;
  return small_recording(options, 10);
}

std::string at(std::uint8_t opcode, std::size_t offset) {
  return m::opcode_name(opcode) + " record at byte " + std::to_string(offset);
}

void read(const std::string& bytes, const ReadLimits& limits = {}) { read_all(bytes, nullptr, limits); }

// Header, the given data records, DataEnd without CRC, Footer without summary, magic.
std::string raw_file(const std::string& data_records) {
  std::string out(m::kMagic);
  std::string header;
  m::put_string(header, "ros2");
  m::put_string(header, "test");
  m::put_record(out, m::kHeader, header);
  out += data_records;
  m::put_record(out, m::kDataEnd, std::string(4, '\0'));
  m::put_record(out, m::kFooter, std::string(20, '\0'));
  return out + std::string(m::kMagic);
}

TEST(IoMcapErrors, EmptyAndForeignFiles) {
  expect_read_error([] { read(""); }, "mem.mcap", "byte 0", "empty file");
  expect_read_error([] { read("# .PCD v0.7\nVERSION 0.7\n"); }, "mem.mcap", "byte 0", "not an MCAP file");
}

// Cut at every length, as a recorder killed mid-write leaves it: each prefix is refused with a
// ReadError, and what was delivered before is exactly the first messages of the whole file.
TEST(IoMcapErrors, EveryTruncationIsRefusedAndKeepsTheMessagesBeforeIt) {
  for (const bool chunked : {true, false}) {
    const std::string whole = recording(McapCompression::lz4, chunked);
    const auto all = read_all(whole);
    std::size_t last_delivered = 0;
    for (std::size_t length = 0; length < whole.size(); ++length) {
      std::string error;
      const auto got = test::read_until_error(std::string_view(whole).substr(0, length), error);
      ASSERT_FALSE(error.empty()) << "prefix of " << length << " bytes was accepted";
      ASSERT_EQ(error.find('\n'), std::string::npos);
      ASSERT_LE(got.size(), all.size());
      for (std::size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i].data, all[i].data) << length;
      ASSERT_GE(got.size(), last_delivered) << "a longer prefix delivered fewer messages";
      last_delivered = got.size();
    }
    EXPECT_EQ(last_delivered, all.size()) << "a file missing only its tail still delivers every message";
  }
}

TEST(IoMcapErrors, TruncatedTailNamesThePlace) {
  const std::string whole = recording(McapCompression::none, false);
  const auto records = top_records(whole);
  const auto& data_end = first_of(records, m::kDataEnd);
  expect_read_error([&] { read(whole.substr(0, data_end.offset)); }, "mem.mcap",
                    "byte " + std::to_string(data_end.offset), "ends without a DataEnd or Footer");
  expect_read_error([&] { read(whole.substr(0, whole.size() - 3)); }, "mem.mcap",
                    "byte " + std::to_string(whole.size() - 8), "closing MCAP magic is missing");
}

TEST(IoMcapErrors, LyingRecordLength) {
  std::string bytes = recording();
  const auto chunk = first_of(top_records(bytes), m::kChunk);
  poke<std::uint64_t>(bytes, chunk.offset + 1, 1ull << 40);
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChunk, chunk.offset), "truncated or bad length");
}

TEST(IoMcapErrors, LyingFieldLength) {
  std::string bytes = recording();
  const auto channel = first_of(top_records(bytes), m::kChannel);
  // id, schema_id, then the topic's u32 length
  poke<std::uint32_t>(bytes, channel.content() + 4, 0xfffffff0u);
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChannel, channel.offset), "field 'topic' needs");
}

TEST(IoMcapErrors, BadChunkCrc) {
  for (const McapCompression c : {McapCompression::none, McapCompression::lz4, McapCompression::zstd}) {
    std::string bytes = recording(c);
    const auto chunk = first_of(top_records(bytes), m::kChunk);
    // message_start_time, message_end_time, uncompressed_size, then uncompressed_crc
    poke<std::uint32_t>(bytes, chunk.content() + 24, 0x12345678u);
    expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChunk, chunk.offset),
                      "chunk CRC mismatch: the file says 0x12345678");
  }
}

TEST(IoMcapErrors, CorruptedUncompressedRecordsFailTheirCrc) {
  std::string bytes = recording(McapCompression::none);
  const auto chunk = first_of(top_records(bytes), m::kChunk);
  bytes[chunk.offset + chunk.length] ^= 0x01;  // the chunk's last byte, inside a message payload
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChunk, chunk.offset), "chunk CRC mismatch");
}

TEST(IoMcapErrors, CorruptedCompressedData) {
  for (const McapCompression c : {McapCompression::lz4, McapCompression::zstd}) {
    std::string bytes = recording(c);
    const auto chunk = first_of(top_records(bytes), m::kChunk);
    // the records start after 8+8+8+4, the compression string (4+3 or 4+4) and their u64 length
    const std::size_t records = chunk.content() + 28 + 4 + (c == McapCompression::lz4 ? 3 : 4) + 8;
    for (std::size_t i = 0; i < 4; ++i) bytes[records + i] ^= 0x5a;  // the frame's magic
    expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChunk, chunk.offset),
                      c == McapCompression::lz4 ? "lz4: " : "zstd: ");
  }
}

TEST(IoMcapErrors, UnknownCompression) {
  std::string bytes = recording(McapCompression::zstd);
  const auto chunk = first_of(top_records(bytes), m::kChunk);
  bytes.replace(chunk.content() + 28 + 4, 4, "brot");
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChunk, chunk.offset), "unknown compression 'brot'");
}

TEST(IoMcapErrors, LyingUncompressedSize) {
  for (const McapCompression c : {McapCompression::none, McapCompression::lz4, McapCompression::zstd}) {
    std::string bytes = recording(c);
    const auto chunk = first_of(top_records(bytes), m::kChunk);
    std::uint64_t size = 0;
    std::memcpy(&size, bytes.data() + chunk.content() + 16, 8);
    poke<std::uint64_t>(bytes, chunk.content() + 16, size + 100);
    expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChunk, chunk.offset),
                      c == McapCompression::none ? "uncompressed chunk holds" : "bytes, the chunk declares");
  }
}

TEST(IoMcapErrors, ChunkOverTheLimit) {
  std::string bytes = recording(McapCompression::zstd);
  const auto chunk = first_of(top_records(bytes), m::kChunk);
  poke<std::uint64_t>(bytes, chunk.content() + 16, 1ull << 50);
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChunk, chunk.offset), "more than the limit");
}

TEST(IoMcapErrors, BadDataSectionCrc) {
  std::string bytes = recording();
  const auto records = top_records(bytes);
  bytes[first_of(records, m::kHeader).content() + 4] ^= 0x20;  // "ros2" -> "Ros2"
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kDataEnd, first_of(records, m::kDataEnd).offset),
                    "data section CRC mismatch");
}

// The data section's CRC is taken record by record, an uncompressed chunk's records through the
// CRC they already have: a byte of the chunk outside its records (message_start_time) or, with no
// chunk CRC to catch it first, inside them still fails it, for every compression.
TEST(IoMcapErrors, DataSectionCrcCoversEveryByteOfTheChunks) {
  for (const McapCompression c : {McapCompression::none, McapCompression::lz4, McapCompression::zstd}) {
    std::string bytes = recording(c);
    const auto records = top_records(bytes);
    const auto chunk = first_of(records, m::kChunk);
    const auto data_end = first_of(records, m::kDataEnd);
    std::string header_changed = bytes;
    header_changed[chunk.content()] ^= 0x01;
    expect_read_error([&] { read(header_changed); }, "mem.mcap", at(m::kDataEnd, data_end.offset),
                      "data section CRC mismatch");
    if (c != McapCompression::none) continue;
    std::string records_changed = bytes;
    poke<std::uint32_t>(records_changed, chunk.content() + 24, 0);  // no chunk CRC
    records_changed[chunk.offset + chunk.length] ^= 0x01;           // inside a message payload
    expect_read_error([&] { read(records_changed); }, "mem.mcap", at(m::kDataEnd, data_end.offset),
                      "data section CRC mismatch");
  }
}

TEST(IoMcapErrors, BadSummaryCrc) {
  std::string bytes = recording();
  const auto records = top_records(bytes);
  bytes[first_of(records, m::kStatistics).content() + 1] ^= 0x01;  // message_count
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kFooter, first_of(records, m::kFooter).offset),
                    "summary CRC mismatch");
}

TEST(IoMcapErrors, FooterPointingElsewhere) {
  std::string bytes = recording();
  const auto footer = first_of(top_records(bytes), m::kFooter);
  poke<std::uint64_t>(bytes, footer.content(), 12);
  poke<std::uint32_t>(bytes, footer.content() + 16, 0);  // no CRC to trip first
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kFooter, footer.offset), "summary_start 12");
}

TEST(IoMcapErrors, TrailingBytesAfterTheMagic) {
  const std::string bytes = recording() + "xx";
  expect_read_error([&] { read(bytes); }, "mem.mcap", "byte " + std::to_string(bytes.size() - 10),
                    "does not end with the MCAP magic");
}

TEST(IoMcapErrors, FirstRecordIsNotAHeader) {
  std::string bytes = recording();
  bytes[8] = static_cast<char>(m::kSchema);
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kSchema, 8), "starts with a Header");
}

TEST(IoMcapErrors, ChannelWithUnknownSchema) {
  std::string bytes = recording(McapCompression::none, false);
  const auto channel = first_of(top_records(bytes), m::kChannel);
  poke<std::uint16_t>(bytes, channel.content() + 2, 7);
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kChannel, channel.offset), "names schema 7");
}

// Unchunked, so the sixth message is a top-level record: the five before it are delivered.
TEST(IoMcapErrors, MessageOnUnknownChannelAfterGoodOnes) {
  std::string bytes = recording(McapCompression::none, false);
  std::vector<test::TopRecord> messages;
  for (const auto& r : top_records(bytes)) {
    if (r.opcode == m::kMessage) messages.push_back(r);
  }
  ASSERT_EQ(messages.size(), 10u);
  poke<std::uint16_t>(bytes, messages[5].content(), 9);
  expect_read_error([&] { read(bytes); }, "mem.mcap", at(m::kMessage, messages[5].offset), "message on channel 9");
  std::string error;
  EXPECT_EQ(test::read_until_error(bytes, error).size(), 5u);
}

TEST(IoMcapErrors, RecordsInsideAChunkAreNamedByTheirChunk) {
  std::string records;
  m::put_record(records, m::kDataEnd, std::string(4, '\0'));
  std::string chunk;
  m::put<std::uint64_t>(chunk, 0);
  m::put<std::uint64_t>(chunk, 0);
  m::put<std::uint64_t>(chunk, records.size());
  m::put<std::uint32_t>(chunk, detail::crc32_of(records));
  m::put_string(chunk, "");
  m::put<std::uint64_t>(chunk, records.size());
  chunk += records;
  std::string data;
  m::put_record(data, m::kChunk, chunk);
  const std::string bytes = raw_file(data);
  const std::size_t chunk_at = first_of(top_records(bytes), m::kChunk).offset;
  expect_read_error([&] { read(bytes); }, "mem.mcap",
                    "DataEnd record at byte 0 of the Chunk at byte " + std::to_string(chunk_at),
                    "a Chunk holds only Schema, Channel and Message records");
}

TEST(IoMcapErrors, BadAttachmentCrc) {
  std::string attachment;
  m::put<std::uint64_t>(attachment, 1);
  m::put<std::uint64_t>(attachment, 2);
  m::put_string(attachment, "calib.yaml");
  m::put_string(attachment, "text/yaml");
  m::put<std::uint64_t>(attachment, 3);
  attachment += "a:1";
  const std::uint32_t good = detail::crc32_of(attachment);
  std::string data;
  std::string ok = attachment;
  m::put<std::uint32_t>(ok, good);
  m::put_record(data, m::kAttachment, ok);
  EXPECT_NO_THROW(read(raw_file(data)));

  std::string bad = attachment;
  m::put<std::uint32_t>(bad, good ^ 1u);
  data.clear();
  m::put_record(data, m::kAttachment, bad);
  expect_read_error([&] { read(raw_file(data)); }, "mem.mcap", at(m::kAttachment, 33), "attachment CRC mismatch");
}

TEST(IoMcapErrors, UnknownOpcodesAreSkipped) {
  std::string data;
  m::put_record(data, 0x80, "private");
  std::string channel;
  m::put<std::uint16_t>(channel, 1);
  m::put<std::uint16_t>(channel, 0);
  m::put_string(channel, "/t");
  m::put_string(channel, "raw");
  m::put<std::uint32_t>(channel, 0);
  m::put_record(data, m::kChannel, channel);
  std::string message;
  m::put<std::uint16_t>(message, 1);
  m::put<std::uint32_t>(message, 1);
  m::put<std::uint64_t>(message, 3);
  m::put<std::uint64_t>(message, 3);
  message += "ok";
  m::put_record(data, m::kMessage, message);
  const auto got = read_all(raw_file(data));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].data, "ok");
}

}  // namespace
}  // namespace cloudshape::io
