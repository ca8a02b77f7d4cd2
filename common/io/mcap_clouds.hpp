// The PointCloud2 messages of an MCAP recording as clouds: rosbag2's layout (profile ros2,
// message encoding cdr) through the same PointCloud2 decoding as the ROS 2 input.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <set>
#include <string>

#include "io/cloud_file.hpp"
#include "io/mcap_reader.hpp"
#include "io/pointcloud2.hpp"
#include "io/read_error.hpp"

namespace cloudshape::io {

struct McapCloud {
  std::size_t index = 0;  // among the file's PointCloud2 messages, from 0, in file order
  std::string topic;
  std::uint64_t log_time = 0;  // ns, as recorded
  RosHeader header;            // the message's own stamp and frame
  PointCloud2 message;         // as recorded, for a player that republishes it unchanged
  CloudFile cloud;
};

// Where reading starts: PointCloud2 message `message` (counted from the file's first one, so
// FILE.mcap#N names the same message whatever the start) and/or `after_ns` after the
// recording's first log time. Through the summary's indexes when the file has usable ones.
struct McapCloudStart {
  std::size_t message = 0;
  std::uint64_t after_ns = 0;
  // Told why the file has no usable index, before it is read from its start (may be empty).
  std::function<void(const std::string& why)> on_unindexed;
  bool at_beginning() const { return message == 0 && after_ns == 0; }
};

// "150": message 150; "2.5s": 2.5 s into the recording. std::invalid_argument saying what is
// expected otherwise.
McapCloudStart parse_mcap_start(const std::string& text);

struct McapCloudHandlers {
  std::function<void(McapCloud&&)> on_cloud;
  // A PointCloud2 message that does not decode (bad CDR, a bad layout): the recording itself
  // is fine, so reading goes on with the next message. The error's place names the message.
  std::function<void(const ReadError&)> on_bad_message;
};

// Messages whose schema is sensor_msgs/msg/PointCloud2 with message encoding "cdr", on the
// given topics (every topic when `topics` is empty); others are skipped. A damaged container is
// a ReadError (read_mcap_file), thrown after every cloud before it was handed over.
// With a start, the summary says whether the index was used (and why not).
McapReadSummary read_mcap_clouds(const std::string& path, const std::set<std::string>& topics,
                                 const McapCloudHandlers& handlers, const ReadLimits& limits = {},
                                 const McapCloudStart& start = {});

// The same for bytes already in memory (tests, the fuzzer).
McapReadSummary read_mcap_clouds_buffer(std::string_view bytes, const std::string& name,
                                        const std::set<std::string>& topics, const McapCloudHandlers& handlers,
                                        const ReadLimits& limits = {}, const McapCloudStart& start = {});

// The PointCloud2 message of that index (as McapCloud::index counts), read again (a replay
// sending a cloud a second time); ReadError when the file has no such message or it does not
// decode. Reading stops at that message, and seeks to it through the index when it can.
McapCloud read_mcap_cloud_at(const std::string& path, std::size_t index, const ReadLimits& limits = {});

// Whether a path names a recording (".mcap", any case).
bool is_mcap_path(const std::string& path);

}  // namespace cloudshape::io
