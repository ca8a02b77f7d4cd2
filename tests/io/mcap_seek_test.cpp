// Starting an MCAP read mid-file: by message number or log time, through the summary's chunk and
// message indexes when they are there and true, by a read from the start otherwise, same messages.
#include <gtest/gtest.h>

#include <gmock/gmock.h>

#include <functional>

#include "io/detail/mcap_format.hpp"
#include "mcap_test_support.hpp"

namespace cloudshape::io {
namespace {
namespace m = detail::mcap;
using test::first_of;
using test::poke;
using test::ReadBack;
using test::small_recording;
using test::top_records;

struct Seeked {
  std::vector<ReadBack> messages;
  std::uint64_t skipped = 0;  // counted messages passed over, as the callback told
  McapReadSummary summary;
};

// Counts only channel "/a" (the even messages of small_recording) when `only_a`.
Seeked read_from(std::string_view bytes, std::uint64_t message, std::uint64_t after_ns, bool only_a = false) {
  Seeked out;
  McapStart start;
  start.message = message;
  start.after_ns = after_ns;
  if (only_a) start.counted = [](const McapChannel& c, const McapSchema*) { return c.topic == "/a"; };
  start.skipped = [&](std::uint64_t n) { out.skipped += n; };
  out.summary = read_mcap_buffer_from(bytes, "mem.mcap", start,
                                      [&](const McapChannel& c, const McapSchema* s, const McapMessage& msg) {
                                        out.messages.push_back({c.topic, s ? s->name : "", msg.sequence, msg.log_time,
                                                                msg.publish_time, std::string(msg.data)});
                                      });
  return out;
}

std::vector<std::uint64_t> log_times(const std::vector<ReadBack>& messages) {
  std::vector<std::uint64_t> out;
  for (const ReadBack& r : messages) out.push_back(r.log_time);
  return out;
}

// small_recording logs message i at 1000 + 10 i.
std::vector<std::uint64_t> times_from(int first, int count = 10) {
  std::vector<std::uint64_t> out;
  for (int i = first; i < count; ++i) out.push_back(1000u + 10u * static_cast<unsigned>(i));
  return out;
}

McapWriterOptions chunks_of(std::size_t bytes, McapCompression compression = McapCompression::zstd) {
  McapWriterOptions o;
  o.chunk_size = bytes;
  o.compression = compression;
  return o;
}

class IoMcapSeek : public ::testing::TestWithParam<McapCompression> {};

TEST_P(IoMcapSeek, StartsAtAMessageThroughTheIndex) {
  const std::string bytes = small_recording(chunks_of(1, GetParam()), 10);  // one message per chunk
  for (int n = 0; n <= 10; ++n) {
    SCOPED_TRACE(n);
    const Seeked s = read_from(bytes, static_cast<std::uint64_t>(n), 0);
    EXPECT_TRUE(s.summary.index_used) << s.summary.index_problem;
    EXPECT_EQ(s.summary.chunks_skipped, static_cast<std::uint64_t>(n));
    EXPECT_EQ(s.skipped, static_cast<std::uint64_t>(n));
    EXPECT_EQ(log_times(s.messages), times_from(n));
    if (n < 10) {
      EXPECT_EQ(s.messages.front().data.size(), static_cast<std::size_t>(30 + 17 * n));
    }
    // The summary was still read and checked; the data section CRC, over skipped chunks, not.
    EXPECT_TRUE(s.summary.summary_crc_checked);
    EXPECT_EQ(s.summary.data_crc_checked, n == 0);
  }
}

TEST_P(IoMcapSeek, StartsAtALogTimeThroughTheIndex) {
  const std::string bytes = small_recording(chunks_of(1, GetParam()), 10);
  // 35 ns after the first message (1000): the first at or after 1035 is message 4 (1040).
  const Seeked s = read_from(bytes, 0, 35);
  EXPECT_TRUE(s.summary.index_used) << s.summary.index_problem;
  EXPECT_EQ(s.summary.chunks_skipped, 4u);
  EXPECT_EQ(s.skipped, 4u);
  EXPECT_EQ(log_times(s.messages), times_from(4));
  const Seeked exact = read_from(bytes, 0, 40);
  EXPECT_EQ(log_times(exact.messages), times_from(4));
  EXPECT_TRUE(read_from(bytes, 0, 1000000).messages.empty());
}

INSTANTIATE_TEST_SUITE_P(Compressions, IoMcapSeek,
                         ::testing::Values(McapCompression::none, McapCompression::lz4, McapCompression::zstd),
                         [](const auto& info) {
                           return std::string(info.param == McapCompression::none  ? "uncompressed"
                                              : info.param == McapCompression::lz4 ? "lz4"
                                                                                   : "zstd");
                         });

// Every layout, every start, messages counted on one channel only: the same messages as a read
// from the start that drops what precedes the start, whether the index is used or not.
TEST(IoMcapSeek, EveryLayoutGivesTheSameMessagesForEveryStart) {
  McapWriterOptions unindexed = chunks_of(200);
  unindexed.indexed = false;
  McapWriterOptions unchunked;
  unchunked.chunked = false;
  struct Case {
    const char* name;
    McapWriterOptions options;
    bool index;
  };
  const Case cases[] = {{"one message per chunk", chunks_of(1), true},
                        {"several per chunk", chunks_of(200), true},
                        {"chunks without indexes", unindexed, false},
                        {"unchunked", unchunked, false}};
  for (const Case& c : cases) {
    const std::string bytes = small_recording(c.options, 10);
    for (int n = 0; n <= 5; ++n) {
      SCOPED_TRACE(std::string(c.name) + ", /a message " + std::to_string(n));
      const Seeked s = read_from(bytes, static_cast<std::uint64_t>(n), 0, true);
      EXPECT_EQ(s.summary.index_used, c.index) << s.summary.index_problem;
      // /a message n is message 2n; everything before it (the /b ones too) is passed over.
      EXPECT_EQ(log_times(s.messages), times_from(2 * n));
      EXPECT_EQ(s.skipped, static_cast<std::uint64_t>(n));
    }
    SCOPED_TRACE(c.name);
    const Seeked both = read_from(bytes, 1, 55, true);  // /a message 1 (1020), at 1055 or later
    EXPECT_EQ(log_times(both.messages), times_from(6));
    EXPECT_EQ(both.skipped, 3u);  // /a messages 0, 1 and 2 passed over
  }
}

TEST(IoMcapSeek, SaysWhyAFileHasNoUsableIndex) {
  McapWriterOptions unindexed = chunks_of(200);
  unindexed.indexed = false;
  EXPECT_EQ(read_from(small_recording(unindexed), 3, 0).summary.index_problem, "the summary has no chunk index");
  McapWriterOptions unchunked;
  unchunked.chunked = false;
  EXPECT_EQ(read_from(small_recording(unchunked), 3, 0).summary.index_problem, "the summary has no chunk index");
}

// Zeroes the data section and summary CRCs, so that a test can damage an index and see what the
// index checks (not the CRCs) make of it, and the read from the start still succeeds.
std::string without_crcs(std::string bytes) {
  const auto records = top_records(bytes);
  poke<std::uint32_t>(bytes, first_of(records, m::kDataEnd).content(), 0);
  poke<std::uint32_t>(bytes, first_of(records, m::kFooter).content() + 16, 0);
  return bytes;
}

std::vector<test::TopRecord> all_of(const std::vector<test::TopRecord>& records, std::uint8_t opcode) {
  std::vector<test::TopRecord> out;
  for (const auto& r : records) {
    if (r.opcode == opcode) out.push_back(r);
  }
  return out;
}

// ChunkIndex fields: message_start_time 0, message_end_time 8, chunk_start_offset 16,
// chunk_length 24, message_index_offsets 32 (u32 length, then u16 channel, u64 offset pairs).
struct Lie {
  const char* name;
  std::function<void(std::string&, const std::vector<test::TopRecord>&)> damage;
  const char* problem;  // what the reason for not using the index says
};

TEST(IoMcapSeek, AnIndexThatLiesIsNotUsed) {
  const std::string good = without_crcs(small_recording(chunks_of(1), 10));
  const auto chunk_index = [](const std::vector<test::TopRecord>& r, std::size_t i) {
    return all_of(r, m::kChunkIndex).at(i).content();
  };
  const Lie lies[] = {
      {"a chunk offset one byte off",
       [&](std::string& b, const auto& r) {
         poke<std::uint64_t>(b, chunk_index(r, 3) + 16, all_of(r, m::kChunk)[3].offset + 1);
       },
       "'s chunk at byte"},
      {"a chunk offset at another chunk",
       [&](std::string& b, const auto& r) {
         poke<std::uint64_t>(b, chunk_index(r, 3) + 16, all_of(r, m::kChunk)[4].offset);
       },
       "the ChunkIndex record at byte"},
      {"a chunk offset at a channel",
       [&](std::string& b, const auto& r) {
         poke<std::uint64_t>(b, chunk_index(r, 0) + 16, first_of(r, m::kChannel).offset);
       },
       "is a Channel record, not a Chunk"},
      {"a chunk offset at the previous chunk's message index",
       [&](std::string& b, const auto& r) {
         poke<std::uint64_t>(b, chunk_index(r, 3) + 16, all_of(r, m::kMessageIndex)[2].offset);
       },
       "over another chunk"},
      {"a wrong chunk length",
       [&](std::string& b, const auto& r) { poke<std::uint64_t>(b, chunk_index(r, 2) + 24, 20); },
       "says the chunk is 20 bytes"},
      {"a chunk length past the data section",
       [&](std::string& b, const auto& r) { poke<std::uint64_t>(b, chunk_index(r, 2) + 24, 1u << 30); },
       "outside the data section"},
      {"wrong log times",
       [&](std::string& b, const auto& r) { poke<std::uint64_t>(b, chunk_index(r, 5) + 8, 999); },
       "log times differ"},
      {"a message index offset at the chunk",
       [&](std::string& b, const auto& r) {
         poke<std::uint64_t>(b, chunk_index(r, 1) + 32 + 4 + 2, all_of(r, m::kChunk)[1].offset);
       },
       "before the end of its chunk"},
      {"a message index offset at the next chunk",
       [&](std::string& b, const auto& r) {
         poke<std::uint64_t>(b, chunk_index(r, 1) + 32 + 4 + 2, all_of(r, m::kChunk)[2].offset);
       },
       "does not fit before"},
      {"a message index of another channel",
       [&](std::string& b, const auto& r) {
         poke<std::uint16_t>(b, all_of(r, m::kMessageIndex)[6].content(), 2);
       },
       "is not the index of channel 1"},
      {"a message index counting half an entry",
       [&](std::string& b, const auto& r) {
         poke<std::uint32_t>(b, all_of(r, m::kMessageIndex)[6].content() + 2, 8);
       },
       "is not the index of channel 1"},
      {"a message index with no entry",
       [&](std::string& b, const auto& r) {
         poke<std::uint32_t>(b, all_of(r, m::kMessageIndex)[6].content() + 2, 0);
       },
       "the message indexes count 9 messages, the Statistics 10"},
      {"statistics counting more",
       [&](std::string& b, const auto& r) { poke<std::uint64_t>(b, first_of(r, m::kStatistics).content(), 11); },
       "the message indexes count 10 messages, the Statistics 11"},
      {"a summary start past the footer",
       [&](std::string& b, const auto& r) {
         poke<std::uint64_t>(b, first_of(r, m::kFooter).content(), b.size());
       },
       "lies outside the file"},
  };
  for (const Lie& lie : lies) {
    SCOPED_TRACE(lie.name);
    std::string bytes = good;
    lie.damage(bytes, top_records(good));
    Seeked s;
    std::string error;
    try {
      s = read_from(bytes, 7, 0);
    } catch (const ReadError& e) {
      // The read from the start checks the summary too: a lie it sees is an error of its own.
      error = e.what();
    }
    if (error.empty()) {
      EXPECT_FALSE(s.summary.index_used);
      EXPECT_THAT(s.summary.index_problem, ::testing::HasSubstr(lie.problem));
      // The read from the start gives the right messages all the same.
      EXPECT_EQ(log_times(s.messages), times_from(7));
      EXPECT_EQ(s.skipped, 7u);
    } else {
      EXPECT_THAT(error, ::testing::StartsWith("mem.mcap: "));
    }
  }
}

TEST(IoMcapSeek, ASummaryCrcMismatchIsNotUsed) {
  std::string bytes = small_recording(chunks_of(1), 10);
  const auto records = top_records(bytes);
  poke<std::uint64_t>(bytes, first_of(records, m::kStatistics).content(), 11);
  std::string error;
  Seeked s;
  try {
    s = read_from(bytes, 7, 0);
  } catch (const ReadError& e) {
    error = e.what();
  }
  // Not used to seek; the read from the start delivers every message, then reports the CRC.
  EXPECT_THAT(error, ::testing::HasSubstr("summary CRC mismatch"));
}

TEST(IoMcapSeek, ATruncatedFileIsReadFromTheStart) {
  const std::string whole = small_recording(chunks_of(1), 10);
  const std::string cut = whole.substr(0, whole.size() / 2);
  std::vector<std::uint64_t> times;
  McapStart start;
  start.message = 2;
  try {
    read_mcap_buffer_from(cut, "cut.mcap", start,
                          [&](const McapChannel&, const McapSchema*, const McapMessage& msg) {
                            times.push_back(msg.log_time);
                          });
    FAIL() << "a truncated file read without error";
  } catch (const ReadError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("truncated"));
  }
  ASSERT_FALSE(times.empty());
  EXPECT_EQ(times.front(), 1020u);  // message 2: the start held, the messages before the cut came
}

}  // namespace
}  // namespace cloudshape::io
