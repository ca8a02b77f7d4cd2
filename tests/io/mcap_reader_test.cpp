// MCAP reader and writer together: what McapWriter writes, read_mcap_* returns message for
// message, whatever the chunking and compression, with every CRC present checked.
#include <gtest/gtest.h>

#include "io/detail/mcap_format.hpp"
#include "io_test_support.hpp"
#include "mcap_test_support.hpp"

namespace cloudshape::io {
namespace {
namespace m = detail::mcap;
using test::read_all;
using test::small_recording;
using test::top_records;

struct Layout {
  const char* name;
  McapCompression compression;
  bool chunked;
};

class IoMcapRoundTrip : public ::testing::TestWithParam<Layout> {};

TEST_P(IoMcapRoundTrip, EveryMessageComesBackExactly) {
  McapWriterOptions options;
  options.compression = GetParam().compression;
  options.chunked = GetParam().chunked;
  options.chunk_size = 200;  // a few messages per chunk
  const std::string bytes = small_recording(options, 10);
  McapReadSummary summary;
  const auto messages = read_all(bytes, &summary);
  ASSERT_EQ(messages.size(), 10u);
  for (int i = 0; i < 10; ++i) {
    SCOPED_TRACE(i);
    const auto& msg = messages[static_cast<std::size_t>(i)];
    EXPECT_EQ(msg.topic, i % 2 ? "/b" : "/a");
    EXPECT_EQ(msg.schema_name, i % 2 ? "" : "pkg/msg/Thing");
    EXPECT_EQ(msg.sequence, static_cast<std::uint32_t>(i / 2 + 1));
    EXPECT_EQ(msg.log_time, 1000u + 10u * static_cast<unsigned>(i));
    EXPECT_EQ(msg.publish_time, 2000u + static_cast<unsigned>(i));
    ASSERT_EQ(msg.data.size(), static_cast<std::size_t>(30 + 17 * i));
    EXPECT_EQ(msg.data[5], static_cast<char>((5 * 7 + i) % 13));
  }
  EXPECT_EQ(summary.profile, "ros2");
  EXPECT_EQ(summary.library, "cloudshape");
  EXPECT_EQ(summary.messages, 10u);
  EXPECT_TRUE(summary.data_crc_checked);
  EXPECT_TRUE(summary.summary_present);
  EXPECT_TRUE(summary.summary_crc_checked);
  if (GetParam().chunked) {
    EXPECT_GE(summary.chunks, 3u);
  } else {
    EXPECT_EQ(summary.chunks, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, IoMcapRoundTrip,
                         ::testing::Values(Layout{"uncompressed_chunks", McapCompression::none, true},
                                           Layout{"lz4_chunks", McapCompression::lz4, true},
                                           Layout{"zstd_chunks", McapCompression::zstd, true},
                                           Layout{"unchunked", McapCompression::none, false}),
                         [](const auto& info) { return std::string(info.param.name); });

// The summary a player seeks with: each Chunk followed by one MessageIndex per channel in it,
// chunk indexes pointing at those chunks, statistics counting every message.
TEST(IoMcapWriter, SummaryIndexesEveryChunk) {
  McapWriterOptions options;
  options.chunk_size = 1;  // one message per chunk
  const std::string bytes = small_recording(options, 6);
  const auto records = top_records(bytes);
  std::size_t chunks = 0, indexes = 0, chunk_indexes = 0, statistics = 0, offsets = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& r = records[i];
    if (r.opcode == m::kChunk) {
      ++chunks;
      ASSERT_LT(i + 1, records.size());
      EXPECT_EQ(records[i + 1].opcode, m::kMessageIndex);
    }
    if (r.opcode == m::kMessageIndex) ++indexes;
    if (r.opcode == m::kSummaryOffset) ++offsets;
    if (r.opcode == m::kChunkIndex) {
      ++chunk_indexes;
      std::uint64_t start = 0;
      std::memcpy(&start, bytes.data() + r.content() + 16, 8);
      ASSERT_LT(start, bytes.size());
      EXPECT_EQ(static_cast<std::uint8_t>(bytes[start]), m::kChunk) << "chunk index " << chunk_indexes;
    }
    if (r.opcode == m::kStatistics) {
      ++statistics;
      std::uint64_t message_count = 0;
      std::memcpy(&message_count, bytes.data() + r.content(), 8);
      EXPECT_EQ(message_count, 6u);
    }
  }
  EXPECT_EQ(chunks, 6u);
  EXPECT_EQ(indexes, 6u);
  EXPECT_EQ(chunk_indexes, 6u);
  EXPECT_EQ(statistics, 1u);
  EXPECT_EQ(offsets, 4u);  // schemas, channels, statistics, chunk indexes
}

TEST(IoMcapWriter, CompressionShrinksRepetitiveChunks) {
  for (McapCompression c : {McapCompression::lz4, McapCompression::zstd}) {
    McapWriterOptions packed;
    packed.compression = c;
    McapWriterOptions plain;
    plain.compression = McapCompression::none;
    EXPECT_LT(small_recording(packed, 40).size() * 2, small_recording(plain, 40).size());
  }
}

TEST(IoMcapReader, ReadsAFileThroughTheMap) {
  const test::TempDir dir;
  const std::string path = dir.file("rec.mcap");
  {
    McapWriter writer(path);
    const auto ch = writer.add_channel(0, "/t", "raw");
    writer.write(ch, 5, 6, "hello");
  }
  std::vector<std::string> seen;
  const McapReadSummary s = read_mcap_file(path, [&](const McapChannel& c, const McapSchema* schema,
                                                     const McapMessage& msg) {
    EXPECT_EQ(schema, nullptr);
    seen.push_back(c.topic + "=" + std::string(msg.data));
  });
  EXPECT_EQ(seen, std::vector<std::string>{"/t=hello"});
  EXPECT_EQ(s.chunks, 1u);
}

TEST(IoMcapReader, AnEmptyRecordingHasNoMessages) {
  std::ostringstream out;
  McapWriter(out, "empty.mcap").close();
  McapReadSummary s;
  EXPECT_TRUE(read_all(out.str(), &s).empty());
  EXPECT_TRUE(s.summary_crc_checked);
}

}  // namespace
}  // namespace cloudshape::io
