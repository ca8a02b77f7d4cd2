// The solver's ROS 2 outputs: each cloud's objects joined, then Detection3DArray and MarkerArray.
#include "ros_results_output.hpp"

#include "dds/ros2_results.hpp"

namespace cloudshape::service {
namespace {

std::string dds_name(const std::string& ros_topic) {
  return ros_topic.empty() ? std::string() : dds::ros2_dds_topic(ros_topic);
}

}  // namespace

RosResultsOutput::RosResultsOutput(dds::Participant& participant, const config::Ros2Config& cfg)
    : cfg_(cfg),
      detections_name_(dds_name(cfg.detections_topic)),
      markers_name_(dds_name(cfg.markers_topic)),
      detections_spec_{detections_name_.c_str()},
      markers_spec_{markers_name_.c_str()} {
  if (!detections_name_.empty()) detections_.emplace(participant, detections_spec_, dds::Traffic::ros2_default);
  if (!markers_name_.empty()) markers_.emplace(participant, markers_spec_, dds::Traffic::ros2_default);
}

int RosResultsOutput::readers() const {
  return (detections_ ? detections_->matched_readers() : 0) + (markers_ ? markers_->matched_readers() : 0);
}

void RosResultsOutput::published(const msg::ShapeResult& result) {
  const auto cloud = joiner_.add(result);
  if (!cloud) return;
  dds::RosResults ros = dds::ros_results(*cloud, cfg_);
  // KEEP_LAST: a slow ROS 2 reader loses old results instead of holding the solver up.
  if (detections_) detections_->write(ros.detections);
  if (markers_) markers_->write(ros.markers);
}

}  // namespace cloudshape::service
