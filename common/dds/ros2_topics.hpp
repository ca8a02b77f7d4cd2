// The ROS 2 topics of the services: DDS topic "rt" + the ROS 2 name, ROS 2's DDS type names
// (idl/ros2), and a PointCloud2 type whose undecodable samples still reach ingest.
#pragma once

#include <string>

#include "dds/topics.hpp"
#include "sensor_msgsPubSubTypes.h"
#include "vision_msgsPubSubTypes.h"
#include "visualization_msgsPubSubTypes.h"

namespace cloudshape::dds {

// What ingest's PointCloud2 reader takes: the cloud, or why its sample did not deserialize (then
// the cloud is empty and the sample becomes the cloud's error result, as on cloudshape_raw_cloud).
struct RosCloudSample {
  sensor_msgs::msg::PointCloud2 cloud;
  std::string undecodable;
};

// sensor_msgs::msg::dds_::PointCloud2_ on the wire; Fast CDR's exceptions and a short sample
// become RosCloudSample::undecodable instead of a silently dropped sample.
class CheckedPointCloud2Type : public sensor_msgs::msg::PointCloud2PubSubType {
 public:
  bool serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) override;
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override;
  std::function<std::uint32_t()> getSerializedSizeProvider(void* data) override;
  bool getKey(void* data, eprosima::fastrtps::rtps::InstanceHandle_t* ihandle, bool force_md5) override;
  void* createData() override;
  void deleteData(void* data) override;
};

using PointCloud2Topic = TopicSpec<RosCloudSample, CheckedPointCloud2Type>;
// For a program that publishes clouds (the tests, the benchmark): the plain generated type. Both
// register the same type name: one participant uses one of the two.
using PointCloud2PublishTopic = TopicSpec<sensor_msgs::msg::PointCloud2, sensor_msgs::msg::PointCloud2PubSubType>;
using DetectionsTopic =
    TopicSpec<vision_msgs::msg::Detection3DArray, vision_msgs::msg::Detection3DArrayPubSubType>;
using MarkersTopic = TopicSpec<visualization_msgs::msg::MarkerArray, visualization_msgs::msg::MarkerArrayPubSubType>;

// The DDS topic of ROS 2 topic `ros_name`: "rt" + "/camera/depth/points"; a relative name gets
// its "/" ("points" -> "rt/points"). Throws DdsError naming it when ROS 2 would refuse the name
// (empty, a character other than letters, digits, "_" and "/", "//", a trailing "/", a token
// starting with a digit).
std::string ros2_dds_topic(const std::string& ros_name);

}  // namespace cloudshape::dds
