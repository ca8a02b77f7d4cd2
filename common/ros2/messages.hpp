// The plain ROS 2 values of common/io (header, PointCloud2) to and from the types fastddsgen
// generates from idl/ros2, and poses from frames: the only place that knows both.
#pragma once

#include "geometry_msgs.h"
#include "io/pointcloud2.hpp"
#include "ros2/solid_view.hpp"
#include "sensor_msgs.h"
#include "std_msgs.h"

namespace cloudshape::ros2 {

std_msgs::msg::Header to_msg(const io::RosHeader& header);
io::RosHeader from_msg(const std_msgs::msg::Header& header);

// Moves the data bytes: no copy of a camera frame.
io::PointCloud2 from_msg(sensor_msgs::msg::PointCloud2&& cloud);
sensor_msgs::msg::PointCloud2 to_msg(io::PointCloud2&& cloud);

geometry_msgs::msg::Point to_point(const Eigen::Vector3d& p);
geometry_msgs::msg::Vector3 to_vector3(const Eigen::Vector3d& v);
// Position the frame's origin, orientation the unit quaternion of its rotation.
geometry_msgs::msg::Pose to_pose(const Frame& frame);

}  // namespace cloudshape::ros2
