// The MCAP fuzz check: a recording is read or refused with one ReadError; what was read, written
// again by McapWriter, reads back the same; its PointCloud2 messages decode to finite points; a
// read from message k on (through the index when the reader trusts it) gives a tail of them.
#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_checks.hpp"
#include "io/mcap_clouds.hpp"
#include "io/mcap_reader.hpp"
#include "io/mcap_writer.hpp"
#include "io/read_error.hpp"

namespace cloudshape::fuzz {
namespace {

struct Seen {
  std::string topic, encoding, schema_name, schema_text;
  std::uint64_t log_time, publish_time;
  std::string data;
  bool operator==(const Seen& o) const {
    return topic == o.topic && encoding == o.encoding && schema_name == o.schema_name &&
           schema_text == o.schema_text && log_time == o.log_time && publish_time == o.publish_time && data == o.data;
  }
};

std::vector<Seen> read_messages(std::string_view bytes, const io::ReadLimits& limits) {
  std::vector<Seen> out;
  io::read_mcap_buffer(
      bytes, "fuzz.mcap",
      [&](const io::McapChannel& c, const io::McapSchema* s, const io::McapMessage& m) {
        out.push_back({c.topic, c.message_encoding, s ? s->name : "", s ? s->data : "", m.log_time, m.publish_time,
                       std::string(m.data)});
      },
      limits);
  return out;
}

// Every message again through the writer (small lz4 chunks, so chunking and indexes are used).
std::string rewrite(const std::vector<Seen>& messages) {
  std::ostringstream out;
  io::McapWriterOptions options;
  options.compression = io::McapCompression::lz4;
  options.chunk_size = 4096;
  io::McapWriter writer(out, "rewrite.mcap", options);
  std::map<std::pair<std::string, std::string>, std::uint16_t> schemas;
  std::map<std::vector<std::string>, std::uint16_t> channels;
  for (const Seen& m : messages) {
    std::uint16_t schema = 0;
    if (!m.schema_name.empty()) {
      auto [it, added] = schemas.try_emplace({m.schema_name, m.schema_text}, 0);
      if (added) it->second = writer.add_schema(m.schema_name, "ros2msg", m.schema_text);
      schema = it->second;
    }
    auto [it, added] = channels.try_emplace({m.topic, m.encoding, std::to_string(schema)}, 0);
    if (added) it->second = writer.add_channel(schema, m.topic, m.encoding);
    writer.write(it->second, m.log_time, m.publish_time, m.data);
  }
  writer.close();
  return out.str();
}

// From message k on: without the index exactly messages[k..]; through it a tail of the messages
// all the same (an index can lie consistently about chunks it lets the reader skip unread, and
// the reader then starts at a true chunk, never elsewhere).
std::string check_seek(std::string_view bytes, const std::vector<Seen>& messages, std::size_t k,
                       const io::ReadLimits& limits) {
  std::vector<Seen> tail;
  io::McapReadSummary summary;
  io::McapStart start;
  start.message = k;
  try {
    summary = io::read_mcap_buffer_from(
        bytes, "fuzz.mcap", start,
        [&](const io::McapChannel& c, const io::McapSchema* s, const io::McapMessage& m) {
          tail.push_back({c.topic, c.message_encoding, s ? s->name : "", s ? s->data : "", m.log_time,
                          m.publish_time, std::string(m.data)});
        },
        limits);
  } catch (const io::ReadError& e) {
    // The index's channels disagreeing with a chunk's is refused: one line, like any refusal.
    return std::string(e.what()).find('\n') == std::string::npos ? "" : "a ReadError message spans lines";
  }
  if (tail.size() > messages.size() ||
      !std::equal(tail.begin(), tail.end(), messages.end() - static_cast<std::ptrdiff_t>(tail.size()))) {
    return "a read from message " + std::to_string(k) + " gave messages the whole read did not end with";
  }
  if (!summary.index_used && tail.size() != messages.size() - std::min(k, messages.size())) {
    return "a read from message " + std::to_string(k) + " without the index gave " + std::to_string(tail.size()) +
           " messages";
  }
  return {};
}

std::string one_line(const io::ReadError& e) {
  return std::string(e.what()).find('\n') == std::string::npos ? "" : "a ReadError message spans lines";
}

}  // namespace

std::string check_mcap_input(std::string_view bytes) {
  const io::ReadLimits limits = fuzz_limits();
  std::vector<Seen> messages;
  try {
    messages = read_messages(bytes, limits);
  } catch (const io::ReadError& e) {
    return one_line(e);
  }
  for (const std::size_t k : {std::size_t{1}, messages.size() / 2}) {
    if (std::string problem = check_seek(bytes, messages, k, limits); !problem.empty()) return problem;
  }
  // A schema without a name cannot be told from "no schema" once rewritten.
  for (const Seen& m : messages) {
    if (m.schema_name.empty() && !m.schema_text.empty()) return {};
  }
  try {
    if (read_messages(rewrite(messages), io::ReadLimits{}) != messages) {
      return "a recording rewritten by McapWriter reads back different messages";
    }
  } catch (const io::ReadError& e) {
    return std::string("McapWriter wrote a file the reader refuses: ") + e.what();
  }
  std::string problem;
  io::read_mcap_clouds_buffer(bytes, "fuzz.mcap", {},
                              {[&](io::McapCloud&& c) {
                                 if (c.cloud.points.size() + c.cloud.non_finite_dropped > limits.max_points) {
                                   problem = "a cloud over the point limit was returned";
                                 }
                                 for (const Point& p : c.cloud.points) {
                                   if (!p.allFinite()) problem = "a non-finite point was returned";
                                 }
                               },
                               [&](const io::ReadError& e) {
                                 if (problem.empty()) problem = one_line(e);
                               }},
                              limits);
  return problem;
}

}  // namespace cloudshape::fuzz
