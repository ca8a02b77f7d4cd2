// Helpers of the MCAP tests: a small recording written by McapWriter into memory, the messages a
// reader returns, and a walk over the top-level records so a test can damage one precisely.
#pragma once

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "io/mcap_reader.hpp"
#include "io/mcap_writer.hpp"

namespace cloudshape::io::test {

struct ReadBack {
  std::string topic, schema_name;
  std::uint32_t sequence;
  std::uint64_t log_time, publish_time;
  std::string data;
};

// `count` messages alternating on two channels ("/a" with a schema, "/b" without), payloads
// of varied length and content so compression and offsets are exercised.
inline std::string small_recording(McapWriterOptions options, int count = 10) {
  std::ostringstream out;
  McapWriter writer(out, "mem.mcap", options);
  const std::uint16_t schema = writer.add_schema("pkg/msg/Thing", "ros2msg", "int32 x\n");
  const std::uint16_t a = writer.add_channel(schema, "/a", "cdr", {{"offered_qos_profiles", ""}});
  const std::uint16_t b = writer.add_channel(0, "/b", "json");
  for (int i = 0; i < count; ++i) {
    std::string payload(static_cast<std::size_t>(30 + 17 * i), '\0');
    for (std::size_t k = 0; k < payload.size(); ++k) payload[k] = static_cast<char>((k * 7 + i) % 13);
    writer.write(i % 2 ? b : a, 1000u + 10u * static_cast<unsigned>(i), 2000u + static_cast<unsigned>(i), payload);
  }
  writer.close();
  return out.str();
}

inline std::vector<ReadBack> read_all(std::string_view bytes, McapReadSummary* summary = nullptr,
                                      const ReadLimits& limits = {}) {
  std::vector<ReadBack> out;
  const McapReadSummary s = read_mcap_buffer(
      bytes, "mem.mcap",
      [&](const McapChannel& channel, const McapSchema* schema, const McapMessage& m) {
        out.push_back({channel.topic, schema ? schema->name : "", m.sequence, m.log_time, m.publish_time,
                       std::string(m.data)});
      },
      limits);
  if (summary) *summary = s;
  return out;
}

// Collects while reading, so what was delivered before a ReadError can be inspected.
inline std::vector<ReadBack> read_until_error(std::string_view bytes, std::string& error) {
  std::vector<ReadBack> out;
  try {
    read_mcap_buffer(bytes, "mem.mcap", [&](const McapChannel& c, const McapSchema*, const McapMessage& m) {
      out.push_back({c.topic, "", m.sequence, m.log_time, m.publish_time, std::string(m.data)});
    });
  } catch (const ReadError& e) {
    error = e.what();
  }
  return out;
}

struct TopRecord {
  std::uint8_t opcode;
  std::size_t offset;  // of the opcode
  std::uint64_t length;
  std::size_t content() const { return offset + 9; }
};

inline std::vector<TopRecord> top_records(const std::string& bytes) {
  std::vector<TopRecord> out;
  for (std::size_t pos = 8; pos + 9 <= bytes.size() - 8;) {
    TopRecord r{static_cast<std::uint8_t>(bytes[pos]), pos, 0};
    std::memcpy(&r.length, bytes.data() + pos + 1, 8);
    out.push_back(r);
    pos += 9 + r.length;
  }
  return out;
}

inline const TopRecord& first_of(const std::vector<TopRecord>& records, std::uint8_t opcode) {
  for (const TopRecord& r : records) {
    if (r.opcode == opcode) return r;
  }
  throw std::runtime_error("no record of opcode " + std::to_string(opcode));
}

template <typename T>
void poke(std::string& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof(T));
}

}  // namespace cloudshape::io::test
