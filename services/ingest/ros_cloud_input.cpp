// cloudshape-ingest's input of one ROS 2 topic: sensor_msgs/PointCloud2, decoded and ingested.
#include "ros_cloud_input.hpp"

#include <algorithm>

#include "dds/ingest_ros_cloud.hpp"
#include "ros2/messages.hpp"

namespace cloudshape::service {

RosCloudInput::RosCloudInput(dds::Participant& participant, const std::string& ros_topic,
                             const config::PipelineConfig& cfg, parallel::ThreadPool* pool)
    : ros_topic_(ros_topic),
      dds_topic_(dds::ros2_dds_topic(ros_topic)),
      spec_{dds_topic_.c_str()},
      reader_(participant, spec_, dds::Traffic::ros2_sensor_data),
      cfg_(cfg),
      pool_(pool) {}

std::optional<CloudRef> RosCloudInput::take() {
  eprosima::fastdds::dds::SampleInfo info;
  if (!reader_.take(sample_, std::chrono::milliseconds(0), &info)) return std::nullopt;
  std::array<std::uint8_t, 16> guid{};
  const auto& writer = info.sample_identity.writer_guid();
  std::copy(std::begin(writer.guidPrefix.value), std::end(writer.guidPrefix.value), guid.begin());
  std::copy(std::begin(writer.entityId.value), std::end(writer.entityId.value), guid.begin() + 12);
  const std::uint64_t id = dds::ros_cloud_id(guid, info.sample_identity.sequence_number().to64long());
  const std::int64_t written_ns = info.source_timestamp.to_ns();
  header_ = dds::ros_cloud_header(ros_topic_, ros2::from_msg(sample_.cloud.header()), id, written_ns);
  return CloudRef{id, ros_topic_, 0};
}

std::vector<msg::FilteredCloud> RosCloudInput::process(bool& failed) {
  failed = false;
  io::PointCloud2 cloud = ros2::from_msg(std::move(sample_.cloud));
  std::vector<msg::FilteredCloud> out;
  try {
    if (!sample_.undecodable.empty()) throw dds::RawCloudError(sample_.undecodable);
    out = dds::ingest_pointcloud2(header_, cloud, cfg_, pool_);
  } catch (const std::exception& e) {
    spdlog::error("cloud {} ({}): {}", header_.cloud_id(), ros_topic_, e.what());
    failed = true;
    out = one(dds::refused_cloud(header_, "ingest", e.what()));
  }
  // The next sample deserializes into the same buffer: a camera frame's megabytes are not
  // allocated and faulted in afresh for every frame.
  sample_.cloud.data(std::move(cloud.data));
  return out;
}

std::vector<std::unique_ptr<Input<msg::FilteredCloud>>> ros_cloud_inputs(
    dds::Participant& participant, const Options& opt, const config::PipelineConfig& cfg, parallel::ThreadPool* pool) {
  std::vector<std::string> topics = cfg.ros2.input_topics;
  topics.insert(topics.end(), opt.ros_topics.begin(), opt.ros_topics.end());
  std::vector<std::string> seen;
  std::vector<std::unique_ptr<Input<msg::FilteredCloud>>> inputs;
  for (const std::string& topic : topics) {
    const std::string dds_topic = dds::ros2_dds_topic(topic);
    if (std::find(seen.begin(), seen.end(), dds_topic) != seen.end()) continue;
    seen.push_back(dds_topic);
    inputs.push_back(std::make_unique<RosCloudInput>(participant, topic, cfg, pool));
  }
  return inputs;
}

}  // namespace cloudshape::service
