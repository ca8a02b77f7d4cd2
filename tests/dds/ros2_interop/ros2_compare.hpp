// The acceptance check of the ROS 2 tests: what a ROS 2 reader received (as JSON, from Cyclone or
// Fast DDS) against the messages cloudshape-recognize's result of the same points makes.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "io/pointcloud2.hpp"
#include "pipeline/result.hpp"
#include "vision_msgs.h"
#include "visualization_msgs.h"

namespace cloudshape::testing {

// The JSON the Cyclone node (ros2_cyclone_node.cpp) prints, from the Fast DDS types.
nlohmann::json detections_json(const vision_msgs::msg::Detection3DArray& detections);
nlohmann::json markers_json(const visualization_msgs::msg::MarkerArray& markers);

// Empty when `detections` and `markers` are what `expected` (recognize's result, its source the
// ROS 2 topic) gives with `header` (config/pipeline.yaml's ros2 style): every string and integer
// equal, every number within 1e-9 relative, each axis of an orientation up to its sign; else the
// first difference.
std::string ros_results_difference(const nlohmann::json& detections, const nlohmann::json& markers,
                                   const pipeline::RecognitionResult& expected, const io::RosHeader& header);

}  // namespace cloudshape::testing
