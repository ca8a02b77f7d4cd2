// The solver's ROS 2 outputs: each cloud's objects joined, then published as Detection3DArray and
// MarkerArray (dds/ros2_results.hpp) with ROS 2's default QoS; their readers count as subscribers.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "common/service.hpp"
#include "config/ros2_config.hpp"
#include "dds/result_joiner.hpp"
#include "dds/ros2_topics.hpp"

namespace cloudshape::service {

class RosResultsOutput : public SideOutput<msg::ShapeResult> {
 public:
  // A topic of "" in `cfg` is not published. Throws dds::DdsError for a bad topic name.
  RosResultsOutput(dds::Participant& participant, const config::Ros2Config& cfg);

  int readers() const override;
  void published(const msg::ShapeResult& result) override;

 private:
  const config::Ros2Config& cfg_;
  std::string detections_name_;  // the specs' names point here: declared before the writers
  std::string markers_name_;
  dds::DetectionsTopic detections_spec_;
  dds::MarkersTopic markers_spec_;
  std::optional<dds::Writer<dds::DetectionsTopic>> detections_;
  std::optional<dds::Writer<dds::MarkersTopic>> markers_;
  dds::ResultJoiner joiner_;
};

}  // namespace cloudshape::service
