// Records recognition results as an MCAP file that Foxglove and Lichtblick open: per cloud a
// vision_msgs Detection3DArray and a visualization_msgs MarkerArray, and optionally the PointCloud2.
#include "recording/result_recorder.hpp"

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>

#include <stdexcept>
#include <utility>

#include "io/pointcloud2_cdr.hpp"
#include "io/ros2_schemas.hpp"
#include "ros2/detections.hpp"
#include "ros2/markers.hpp"

namespace cloudshape::recording {
namespace {

// The generated type's own CDR serialization (Fast CDR, no participant): the bytes a ROS 2 node
// publishes and rosbag2 records, little-endian after the encapsulation header.
template <class Message>
std::string cdr_bytes(const Message& message) {
  constexpr std::size_t kEncapsulation = 4;
  std::string out(kEncapsulation + Message::getCdrSerializedSize(message), '\0');
  eprosima::fastcdr::FastBuffer buffer(out.data(), out.size());
  eprosima::fastcdr::Cdr cdr(buffer, eprosima::fastcdr::Cdr::LITTLE_ENDIANNESS, eprosima::fastcdr::Cdr::DDS_CDR);
  cdr.serialize_encapsulation();
  message.serialize(cdr);
  out.resize(cdr.getSerializedDataLength());
  return out;
}

io::McapWriterOptions writer_options(const RecorderSettings& settings) {
  io::McapWriterOptions options;
  options.compression = settings.compression;
  return options;
}

}  // namespace

ResultRecorder::ResultRecorder(const std::string& path, RecorderSettings settings)
    : settings_(std::move(settings)), writer_(path, writer_options(settings_)) {
  if (!settings_.ros2.detections_topic.empty()) {
    const auto schema = writer_.add_schema(io::kDetection3DArraySchemaName, "ros2msg",
                                           io::ros2_schema_text(io::kDetection3DArraySchemaName));
    detections_ = writer_.add_channel(schema, settings_.ros2.detections_topic, "cdr");
  }
  if (!settings_.ros2.markers_topic.empty()) {
    const auto schema =
        writer_.add_schema(io::kMarkerArraySchemaName, "ros2msg", io::ros2_schema_text(io::kMarkerArraySchemaName));
    markers_ = writer_.add_channel(schema, settings_.ros2.markers_topic, "cdr");
  }
}

void ResultRecorder::record(const pipeline::RecognitionResult& result, const io::RosHeader& header,
                            std::uint64_t log_time_ns, const io::PointCloud2* cloud, const std::string& cloud_topic) {
  const std::uint64_t publish_time =
      static_cast<std::uint64_t>(header.stamp.sec) * 1'000'000'000ull + header.stamp.nanosec;
  if (settings_.clouds && cloud != nullptr) {
    const std::string& topic = cloud_topic.empty() ? settings_.cloud_topic : cloud_topic;
    auto channel = cloud_channels_.find(topic);
    if (channel == cloud_channels_.end()) {
      if (cloud_schema_ == 0) {
        cloud_schema_ = writer_.add_schema(io::kPointCloud2SchemaName, "ros2msg",
                                           io::ros2_schema_text(io::kPointCloud2SchemaName));
      }
      channel = cloud_channels_.emplace(topic, writer_.add_channel(cloud_schema_, topic, "cdr")).first;
    }
    writer_.write(channel->second, log_time_ns, publish_time, io::pointcloud2_to_cdr(*cloud));
    ++messages_;
  }
  if (detections_ != 0) {
    const auto msg = ros2::to_detection_array(result, header);
    writer_.write(detections_, log_time_ns, publish_time, cdr_bytes(msg));
    ++messages_;
  }
  if (markers_ != 0) {
    const auto msg = ros2::to_marker_array(result, header, settings_.ros2);
    writer_.write(markers_, log_time_ns, publish_time, cdr_bytes(msg));
    ++messages_;
  }
}

void ResultRecorder::close() { writer_.close(); }

io::RosHeader file_header(std::uint64_t time_ns, const config::Ros2Config& ros2) {
  io::RosHeader header;
  header.stamp.sec = static_cast<std::int32_t>(time_ns / 1'000'000'000ull);
  header.stamp.nanosec = static_cast<std::uint32_t>(time_ns % 1'000'000'000ull);
  header.frame_id = ros2.file_frame_id;
  return header;
}

}  // namespace cloudshape::recording
