// The plain ROS 2 values of common/io (header, PointCloud2) to and from the types fastddsgen
// generates from idl/ros2, and poses from frames.
#include "ros2/messages.hpp"

#include <Eigen/Geometry>

namespace cloudshape::ros2 {

std_msgs::msg::Header to_msg(const io::RosHeader& header) {
  std_msgs::msg::Header out;
  out.stamp().sec(header.stamp.sec);
  out.stamp().nanosec(header.stamp.nanosec);
  out.frame_id(header.frame_id);
  return out;
}

io::RosHeader from_msg(const std_msgs::msg::Header& header) {
  return {{header.stamp().sec(), header.stamp().nanosec()}, header.frame_id()};
}

io::PointCloud2 from_msg(sensor_msgs::msg::PointCloud2&& cloud) {
  io::PointCloud2 out;
  out.header = from_msg(cloud.header());
  out.height = cloud.height();
  out.width = cloud.width();
  out.fields.reserve(cloud.fields().size());
  for (const sensor_msgs::msg::PointField& f : cloud.fields()) {
    out.fields.push_back({f.name(), f.offset(), f.datatype(), f.count()});
  }
  out.is_bigendian = cloud.is_bigendian();
  out.point_step = cloud.point_step();
  out.row_step = cloud.row_step();
  out.data = std::move(cloud.data());
  out.is_dense = cloud.is_dense();
  return out;
}

sensor_msgs::msg::PointCloud2 to_msg(io::PointCloud2&& cloud) {
  sensor_msgs::msg::PointCloud2 out;
  out.header(to_msg(cloud.header));
  out.height(cloud.height);
  out.width(cloud.width);
  for (const io::PointField& f : cloud.fields) {
    sensor_msgs::msg::PointField field;
    field.name(f.name);
    field.offset(f.offset);
    field.datatype(f.datatype);
    field.count(f.count);
    out.fields().push_back(std::move(field));
  }
  out.is_bigendian(cloud.is_bigendian);
  out.point_step(cloud.point_step);
  out.row_step(cloud.row_step);
  out.data(std::move(cloud.data));
  out.is_dense(cloud.is_dense);
  return out;
}

geometry_msgs::msg::Point to_point(const Eigen::Vector3d& p) {
  geometry_msgs::msg::Point out;
  out.x(p.x());
  out.y(p.y());
  out.z(p.z());
  return out;
}

geometry_msgs::msg::Vector3 to_vector3(const Eigen::Vector3d& v) {
  geometry_msgs::msg::Vector3 out;
  out.x(v.x());
  out.y(v.y());
  out.z(v.z());
  return out;
}

geometry_msgs::msg::Pose to_pose(const Frame& frame) {
  const Eigen::Quaterniond q = Eigen::Quaterniond(frame.rotation).normalized();
  geometry_msgs::msg::Pose out;
  out.position(to_point(frame.origin));
  out.orientation().x(q.x());
  out.orientation().y(q.y());
  out.orientation().z(q.z());
  out.orientation().w(q.w());
  return out;
}

}  // namespace cloudshape::ros2
