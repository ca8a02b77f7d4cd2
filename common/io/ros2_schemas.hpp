// The ros2msg schema texts a recording carries for the messages cloudshape writes: the message's
// definition, then each type it uses after a "MSG: pkg/Type" separator, as rosbag2 stores them.
#pragma once

#include <string>

namespace cloudshape::io {

inline constexpr const char* kPointCloud2SchemaName = "sensor_msgs/msg/PointCloud2";
inline constexpr const char* kDetection3DArraySchemaName = "vision_msgs/msg/Detection3DArray";
inline constexpr const char* kMarkerArraySchemaName = "visualization_msgs/msg/MarkerArray";

// The text for one of the names above (the layouts of idl/ros2, ROS 2 Humble and later);
// std::invalid_argument for any other name.
std::string ros2_schema_text(const std::string& schema_name);

}  // namespace cloudshape::io
