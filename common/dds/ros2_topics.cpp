// The ROS 2 topics of the services: DDS names from ROS 2 names, and the checked PointCloud2 type.
#include "dds/ros2_topics.hpp"

#include <fastcdr/exceptions/Exception.h>

#include <cctype>

#include "dds/participant.hpp"

namespace cloudshape::dds {
namespace {

sensor_msgs::msg::PointCloud2* cloud_of(void* data) { return &static_cast<RosCloudSample*>(data)->cloud; }

}  // namespace

bool CheckedPointCloud2Type::serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) {
  return PointCloud2PubSubType::serialize(cloud_of(data), payload);
}

bool CheckedPointCloud2Type::deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) {
  auto* sample = static_cast<RosCloudSample*>(data);
  sample->undecodable.clear();
  std::string problem = "it ends too early";
  try {
    if (PointCloud2PubSubType::deserialize(payload, &sample->cloud)) return true;
  } catch (const eprosima::fastcdr::exception::Exception& e) {
    problem = e.what();
  }
  // Fast DDS drops a sample whose deserialize returns false: delivered, it gets its error result.
  sample->cloud = sensor_msgs::msg::PointCloud2();
  sample->undecodable = "the sample does not deserialize as sensor_msgs/PointCloud2: " + problem;
  return true;
}

std::function<std::uint32_t()> CheckedPointCloud2Type::getSerializedSizeProvider(void* data) {
  return PointCloud2PubSubType::getSerializedSizeProvider(cloud_of(data));
}

bool CheckedPointCloud2Type::getKey(void* data, eprosima::fastrtps::rtps::InstanceHandle_t* ihandle,
                                    bool force_md5) {
  return PointCloud2PubSubType::getKey(cloud_of(data), ihandle, force_md5);
}

void* CheckedPointCloud2Type::createData() { return new RosCloudSample(); }

void CheckedPointCloud2Type::deleteData(void* data) { delete static_cast<RosCloudSample*>(data); }

std::string ros2_dds_topic(const std::string& ros_name) {
  const auto refuse = [&](const std::string& why) {
    throw DdsError("ROS 2 topic '" + ros_name + "': " + why);
  };
  if (ros_name.empty() || ros_name == "/") refuse("empty");
  const std::string absolute = ros_name.front() == '/' ? ros_name : "/" + ros_name;
  if (absolute.back() == '/') refuse("ends with '/'");
  for (std::size_t i = 0; i < absolute.size(); ++i) {
    const char c = absolute[i];
    if (c == '/') {
      if (absolute[i + 1] == '/') refuse("holds '//'");
      if (std::isdigit(static_cast<unsigned char>(absolute[i + 1]))) refuse("a name token starts with a digit");
    } else if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') {
      refuse(std::string("holds '") + c + "' (ROS 2 names take letters, digits, '_' and '/')");
    }
  }
  return "rt" + absolute;
}

}  // namespace cloudshape::dds
