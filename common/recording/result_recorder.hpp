// Records recognition results as an MCAP file that Foxglove and Lichtblick open: per cloud a
// vision_msgs Detection3DArray and a visualization_msgs MarkerArray, and optionally the PointCloud2.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "config/ros2_config.hpp"
#include "io/mcap_writer.hpp"
#include "io/pointcloud2.hpp"
#include "pipeline/result.hpp"

namespace cloudshape::recording {

struct RecorderSettings {
  bool clouds = false;  // also record each input cloud as sensor_msgs/PointCloud2
  io::McapCompression compression = io::McapCompression::zstd;
  config::Ros2Config ros2;  // the result topics and the markers' look
  // Where a cloud without a topic of its own (one read from a file) is recorded.
  std::string cloud_topic = "/cloudshape/points";
};

// Profile ros2, schemas ros2msg, messages cdr; the MCAP summary, indexes and statistics let a
// player seek. Throws std::runtime_error naming the file when it cannot be written.
class ResultRecorder {
public:
  ResultRecorder(const std::string& path, RecorderSettings settings);

  // `header` stamps every message (the input cloud's); `cloud` is recorded when settings.clouds
  // (null: none), on `cloud_topic` or, when that is empty, on settings.cloud_topic.
  void record(const pipeline::RecognitionResult& result, const io::RosHeader& header, std::uint64_t log_time_ns,
              const io::PointCloud2* cloud = nullptr, const std::string& cloud_topic = "");
  void close();

  bool records_clouds() const { return settings_.clouds; }
  std::uint64_t messages() const { return messages_; }

private:
  RecorderSettings settings_;
  io::McapWriter writer_;
  std::uint16_t detections_ = 0, markers_ = 0, cloud_schema_ = 0;
  std::map<std::string, std::uint16_t> cloud_channels_;
  std::uint64_t messages_ = 0;
};

// The header a result of a cloud without one gets (a file): `time_ns` in the configured frame.
io::RosHeader file_header(std::uint64_t time_ns, const config::Ros2Config& ros2);

}  // namespace cloudshape::recording
