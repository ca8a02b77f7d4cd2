// cloudshape-ingest's input of one ROS 2 topic: sensor_msgs/PointCloud2 with ROS 2's sensor-data
// QoS, each sample decoded and ingested as a raw cloud is (dds/ingest_ros_cloud.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "common/service.hpp"
#include "dds/ros2_topics.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::service {

class RosCloudInput : public Input<msg::FilteredCloud> {
 public:
  // `ros_topic` is a ROS 2 name ("/camera/depth/points"); throws dds::DdsError for a bad one.
  RosCloudInput(dds::Participant& participant, const std::string& ros_topic, const config::PipelineConfig& cfg,
                parallel::ThreadPool* pool);

  std::string topic() const override { return dds_topic_; }
  eprosima::fastdds::dds::Condition& data_available() override { return reader_.data_available(); }
  std::optional<CloudRef> take() override;
  std::vector<msg::FilteredCloud> process(bool& failed) override;

 private:
  std::string ros_topic_;
  std::string dds_topic_;  // the spec's name points here: declared before the reader
  dds::PointCloud2Topic spec_;
  dds::Reader<dds::PointCloud2Topic> reader_;
  const config::PipelineConfig& cfg_;
  parallel::ThreadPool* pool_;
  dds::RosCloudSample sample_;
  msg::CloudHeader header_;
};

// One input per topic of ros2.input_topics and --ros-topic, each topic once.
std::vector<std::unique_ptr<Input<msg::FilteredCloud>>> ros_cloud_inputs(
    dds::Participant& participant, const Options& opt, const config::PipelineConfig& cfg, parallel::ThreadPool* pool);

}  // namespace cloudshape::service
