// The ROS 2 messages of one cloud's joined result (the solver's per-object ShapeResult samples):
// Detection3DArray and MarkerArray, stamped with the cloud's ROS 2 header.
#pragma once

#include <vector>

#include "cloudshape.h"
#include "config/ros2_config.hpp"
#include "io/pointcloud2.hpp"
#include "vision_msgs.h"
#include "visualization_msgs.h"

namespace cloudshape::dds {

// The cloud's sensor header (a PointCloud2's std_msgs/Header); for a cloud without one (a file:
// empty frame_id) ros2.file_frame_id, stamped with the injection time.
io::RosHeader ros_result_header(const msg::CloudHeader& header, const config::Ros2Config& cfg);

struct RosResults {
  vision_msgs::msg::Detection3DArray detections;
  visualization_msgs::msg::MarkerArray markers;
};

// `objects`: every object's result message of one cloud, in object order (dds::ResultJoiner).
RosResults ros_results(const std::vector<msg::ShapeResult>& objects, const config::Ros2Config& cfg);

}  // namespace cloudshape::dds
