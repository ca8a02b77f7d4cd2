// The ROS 2 types on the wire: ROS 2's DDS type names, and a PointCloud2's plain CDR bytes exactly
// as the ROS 2 layout puts them (written here by hand), so any ROS 2 node can read what we send.
#include <gtest/gtest.h>

#include <cstring>
#include <fastdds/rtps/common/SerializedPayload.h>

#include "io/pointcloud2_encode.hpp"
#include "ros2/messages.hpp"
#include "sensor_msgsPubSubTypes.h"
#include "vision_msgsPubSubTypes.h"
#include "visualization_msgsPubSubTypes.h"

namespace cloudshape::ros2 {
namespace {

// Little-endian plain CDR (XCDR1): each primitive aligned to its size from the start of the body.
class CdrWriter {
 public:
  CdrWriter() : bytes_{0x00, 0x01, 0x00, 0x00} {}  // encapsulation CDR_LE, options 0
  template <typename T>
  void put(T v) {
    while ((bytes_.size() - 4) % sizeof(T) != 0) bytes_.push_back(0);
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    bytes_.insert(bytes_.end(), raw, raw + sizeof(T));
  }
  void put_string(const std::string& s) {
    put<std::uint32_t>(static_cast<std::uint32_t>(s.size() + 1));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

std::vector<std::uint8_t> serialize(sensor_msgs::msg::PointCloud2& m) {
  sensor_msgs::msg::PointCloud2PubSubType type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(&m)());
  EXPECT_TRUE(type.serialize(&m, &payload));
  return std::vector<std::uint8_t>(payload.data, payload.data + payload.length);
}

TEST(Ros2Wire, TypesHaveTheRos2DdsNames) {
  EXPECT_EQ(sensor_msgs::msg::PointCloud2PubSubType().getName(), std::string("sensor_msgs::msg::dds_::PointCloud2_"));
  EXPECT_EQ(vision_msgs::msg::Detection3DArrayPubSubType().getName(),
            std::string("vision_msgs::msg::dds_::Detection3DArray_"));
  EXPECT_EQ(visualization_msgs::msg::MarkerArrayPubSubType().getName(),
            std::string("visualization_msgs::msg::dds_::MarkerArray_"));
}

TEST(Ros2Wire, PointCloud2BytesAreTheRos2Layout) {
  io::PointCloud2Layout layout;
  layout.rgb = false;
  layout.point_step = 12;
  io::PointCloud2 plain =
      io::encode_pointcloud2({Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-0.5, 0.25, 8)}, {}, layout, {{-7, 99}, "cam"});
  const std::vector<std::uint8_t> data = plain.data;
  sensor_msgs::msg::PointCloud2 msg = to_msg(std::move(plain));

  CdrWriter w;
  w.put<std::int32_t>(-7);
  w.put<std::uint32_t>(99);
  w.put_string("cam");
  w.put<std::uint32_t>(1);  // height
  w.put<std::uint32_t>(2);  // width
  w.put<std::uint32_t>(3);  // fields
  for (const char* name : {"x", "y", "z"}) {
    w.put_string(name);
    w.put<std::uint32_t>(static_cast<std::uint32_t>(4 * (name[0] - 'x')));
    w.put<std::uint8_t>(7);
    w.put<std::uint32_t>(1);
  }
  w.put<std::uint8_t>(0);    // is_bigendian
  w.put<std::uint32_t>(12);  // point_step
  w.put<std::uint32_t>(24);  // row_step
  w.put<std::uint32_t>(24);  // data
  for (std::uint8_t b : data) w.put<std::uint8_t>(b);
  w.put<std::uint8_t>(1);  // is_dense

  const std::vector<std::uint8_t> bytes = serialize(msg);
  ASSERT_GE(bytes.size(), w.bytes().size());
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(w.bytes().size())),
            w.bytes());
  // Anything after is alignment padding.
  for (std::size_t i = w.bytes().size(); i < bytes.size(); ++i) EXPECT_EQ(bytes[i], 0) << i;
}

TEST(Ros2Wire, PointCloud2RoundTripKeepsEveryPoint) {
  PointList points;
  for (int i = 0; i < 200; ++i) points.emplace_back(0.01 * i, -0.02 * i, 1.0 + 1e-7 * i);
  io::PointCloud2 plain = io::encode_pointcloud2(points, {}, io::float64_layout(), {{5, 6}, "frame"});
  sensor_msgs::msg::PointCloud2 msg = to_msg(std::move(plain));
  const std::vector<std::uint8_t> bytes = serialize(msg);

  sensor_msgs::msg::PointCloud2PubSubType type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::memcpy(payload.data, bytes.data(), bytes.size());
  payload.length = static_cast<std::uint32_t>(bytes.size());
  sensor_msgs::msg::PointCloud2 back;
  ASSERT_TRUE(type.deserialize(&payload, &back));
  const io::PointCloud2 decoded = from_msg(std::move(back));
  EXPECT_EQ(decoded.header.stamp.sec, 5);
  EXPECT_EQ(decoded.header.frame_id, "frame");
  const io::CloudFile cloud = io::decode_pointcloud2(decoded, "round trip");
  ASSERT_EQ(cloud.points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(cloud.points[i], points[i]);
}

}  // namespace
}  // namespace cloudshape::ros2
