// The MCAP records a reader hands out and a writer takes in, as plain values.
// Field meanings follow the MCAP specification (mcap.dev/spec); times are nanoseconds.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace cloudshape::io {

enum class McapCompression : std::uint8_t { none, lz4, zstd };

struct McapSchema {
  std::uint16_t id = 0;
  std::string name;      // e.g. "sensor_msgs/msg/PointCloud2"
  std::string encoding;  // e.g. "ros2msg"
  std::string data;      // the schema text
};

struct McapChannel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;  // 0: no schema
  std::string topic;
  std::string message_encoding;  // e.g. "cdr"
  std::map<std::string, std::string> metadata;
};

// A message as the reader sees it: `data` points into the reader's buffers and is valid
// only during the visitor call that receives it.
struct McapMessage {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0;
  std::uint64_t publish_time = 0;
  std::string_view data;
};

}  // namespace cloudshape::io
