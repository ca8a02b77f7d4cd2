// What ingest does with a ROS 2 PointCloud2 and the solver with a cloud's results, without DDS
// traffic: ids, headers, each bad layout's error text, the same filtered clouds as a raw cloud of
// the same points, ROS 2 topic names, and undecodable samples kept.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <set>

#include "dds/convert.hpp"
#include "dds/ingest_ros_cloud.hpp"
#include "dds/participant.hpp"
#include "dds/ros2_results.hpp"
#include "dds/ros2_topics.hpp"
#include "io/pointcloud2_encode.hpp"
#include "ros2/messages.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape::dds {
namespace {

using ::testing::HasSubstr;

PointList box_points(std::size_t n) {
  std::mt19937_64 rng(5);
  return synth::sample_solid_surface(synth::random_solid(synth::ShapeKind::box, rng, 20.0), n, rng);
}

const io::RosHeader kHeader{{1700000000, 250}, "camera_depth_optical_frame"};

std::string refusal(const io::PointCloud2& cloud, const config::InputConfig& limits = {}) {
  try {
    pointcloud2_points(cloud, limits);
  } catch (const RawCloudError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(IngestRosCloud, CloudIdFollowsTheSampleIdentity) {
  std::array<std::uint8_t, 16> guid{};
  for (std::size_t i = 0; i < guid.size(); ++i) guid[i] = static_cast<std::uint8_t>(3 * i + 1);
  std::set<std::uint64_t> ids;
  for (std::int64_t seq = 1; seq <= 1000; ++seq) ids.insert(ros_cloud_id(guid, seq));
  EXPECT_EQ(ids.size(), 1000u);
  EXPECT_EQ(ros_cloud_id(guid, 17), ros_cloud_id(guid, 17));  // every replica computes the same
  std::array<std::uint8_t, 16> other = guid;
  other[15] ^= 1;
  EXPECT_NE(ros_cloud_id(other, 17), ros_cloud_id(guid, 17));
  EXPECT_EQ(ids.count(0), 0u);
  // Spread over two lanes about evenly.
  std::size_t even = 0;
  for (std::uint64_t id : ids) even += id % 2 == 0;
  EXPECT_NEAR(static_cast<double>(even), 500.0, 60.0);
}

TEST(IngestRosCloud, HeaderCarriesTopicStampAndFrame) {
  const msg::CloudHeader h = ros_cloud_header("/camera/depth/points", kHeader, 99, 123456789);
  EXPECT_EQ(h.cloud_id(), 99u);
  EXPECT_EQ(h.source(), "/camera/depth/points");
  EXPECT_EQ(h.inject_time_ns(), 123456789);
  EXPECT_EQ(h.sensor().stamp_sec(), kHeader.stamp.sec);
  EXPECT_EQ(h.sensor().stamp_nanosec(), kHeader.stamp.nanosec);
  EXPECT_EQ(h.sensor().frame_id(), kHeader.frame_id);
  EXPECT_FALSE(h.error());
}

// The same points reach preprocessing as from a raw cloud: identical filtered clouds.
TEST(IngestRosCloud, SameFilteredCloudsAsARawCloudOfTheSamePoints) {
  const config::PipelineConfig cfg;
  PointList points = box_points(3000);
  points[10].x() = std::numeric_limits<double>::quiet_NaN();
  for (const io::PointCloud2Layout& layout : {io::PointCloud2Layout{}, io::float64_layout()}) {
    const io::PointCloud2 cloud = io::encode_pointcloud2(points, {}, layout, kHeader);
    const RawCloudPoints decoded = pointcloud2_points(cloud, cfg.input);
    EXPECT_EQ(decoded.non_finite_dropped, 1u);
    msg::RawCloud raw = to_raw_cloud(decoded.points, {});
    const msg::CloudHeader header = ros_cloud_header("/t", kHeader, 5, 0);
    raw.header(header);
    const std::vector<msg::FilteredCloud> a = ingest_pointcloud2(header, cloud, cfg);
    const std::vector<msg::FilteredCloud> b = ingest_raw_cloud(raw, cfg);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].cloud().xyz(), b[i].cloud().xyz());
      EXPECT_EQ(a[i].cloud().resolution(), b[i].cloud().resolution());
      EXPECT_EQ(a[i].cloud().scan_lines(), b[i].cloud().scan_lines());
      EXPECT_EQ(a[i].header().sensor().frame_id(), kHeader.frame_id);
      EXPECT_EQ(a[i].header().object_count(), b[i].header().object_count());
    }
  }
}

TEST(IngestRosCloud, OrganizedCloudKeepsItsGrid) {
  GridLayout grid;
  grid.width = 80;
  grid.height = 50;
  const PointList points = box_points(2000);
  for (std::uint32_t i = 0; i < 2000; ++i) grid.pixel.push_back(2 * i);
  const RawCloudPoints decoded =
      pointcloud2_points(io::encode_pointcloud2(points, grid, io::float64_layout(), kHeader), {});
  EXPECT_EQ(decoded.grid.pixel, grid.pixel);
  EXPECT_EQ(decoded.grid.width, 80u);
  EXPECT_EQ(decoded.grid.height, 50u);
  EXPECT_EQ(decoded.non_finite_dropped, 2000u);
  EXPECT_EQ(decoded.points, points);
}

// Item 3 of issue 15, as the reason of the cloud's error result.
TEST(IngestRosCloud, EveryBadLayoutIsRefusedNamingTheProblem) {
  const io::PointCloud2 good = io::encode_pointcloud2(box_points(100), {}, {}, kHeader);
  io::PointCloud2 c = good;
  c.fields.erase(c.fields.begin() + 1);
  EXPECT_EQ(refusal(c), "fields: no field named 'y' (fields: x, z, rgb)");
  c = good;
  c.fields[0].offset = 13;
  EXPECT_EQ(refusal(c), "field 'x': offset 13 + 1 x FLOAT32 ends at byte 17, past point_step 16");
  c = good;
  c.fields[3].count = 2;
  EXPECT_EQ(refusal(c), "field 'rgb': offset 12 + 2 x FLOAT32 ends at byte 20, past point_step 16");
  c = good;
  c.data.pop_back();
  EXPECT_EQ(refusal(c), "data: 1599 bytes, fewer than row_step * height = 1600 x 1 = 1600 (width x height = 100 x 1)");
  c = good;
  c.width = 50;
  c.height = 2;
  c.row_step = 50 * 16;  // the same bytes as 2 rows of 50: accepted, as it should be
  EXPECT_EQ(refusal(c), "(accepted)");
  c.height = 3;
  EXPECT_THAT(refusal(c), HasSubstr("data: 1600 bytes, fewer than row_step * height = 800 x 3 = 2400"));
  c = good;
  c.width = 101;
  EXPECT_EQ(refusal(c), "row_step: 1600 is less than width * point_step = 101 x 16 = 1616");
}

TEST(IngestRosCloud, NoUsablePointsLimitsAndCoordinates) {
  io::PointCloud2 empty = io::encode_pointcloud2({}, {}, {}, kHeader);
  EXPECT_EQ(refusal(empty), "no points (width x height = 0 x 1)");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refusal(io::encode_pointcloud2(PointList(20, Point(nan, 0, 0)), {}, {}, kHeader)),
            "no usable points (all 20 points have NaN or infinite coordinates)");
  config::InputConfig limits;
  limits.max_points = 99;
  EXPECT_EQ(refusal(io::encode_pointcloud2(box_points(100), {}, {}, kHeader), limits),
            "width * height: 100 x 1 = 100 points, more than the limit of 99");
  limits = {};
  limits.max_bytes = 1000;
  EXPECT_EQ(refusal(io::encode_pointcloud2(box_points(100), {}, {}, kHeader), limits),
            "data: 1600 bytes, more than the limit of 1000");
  PointList far = box_points(10);
  far[4].z() = 1e31;
  EXPECT_THAT(refusal(io::encode_pointcloud2(far, {}, io::float64_layout(), kHeader)),
              HasSubstr("beyond input.max_coordinate"));
}

TEST(IngestRosCloud, UndecodableSampleIsDeliveredWithItsProblem) {
  CheckedPointCloud2Type type;
  const std::string garbage = std::string("\x00\x01\x00\x00", 4) + "\x05\x00\x00\x00\xff";
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(garbage.size()));
  std::copy(garbage.begin(), garbage.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(garbage.size());
  RosCloudSample sample;
  sample.cloud.width(7);
  ASSERT_TRUE(type.deserialize(&payload, &sample));
  EXPECT_THAT(sample.undecodable, HasSubstr("the sample does not deserialize as sensor_msgs/PointCloud2"));
  EXPECT_EQ(sample.cloud.width(), 0u);  // nothing half-read is left
  // And a good one clears the problem.
  sensor_msgs::msg::PointCloud2 good = ros2::to_msg(io::encode_pointcloud2(box_points(5), {}, {}, kHeader));
  sensor_msgs::msg::PointCloud2PubSubType plain;
  eprosima::fastrtps::rtps::SerializedPayload_t ok(plain.getSerializedSizeProvider(&good)());
  ASSERT_TRUE(plain.serialize(&good, &ok));
  ASSERT_TRUE(type.deserialize(&ok, &sample));
  EXPECT_EQ(sample.undecodable, "");
  EXPECT_EQ(sample.cloud.width(), 5u);
}

TEST(Ros2Topics, DdsNamesOfRos2Names) {
  EXPECT_EQ(ros2_dds_topic("/camera/depth/points"), "rt/camera/depth/points");
  EXPECT_EQ(ros2_dds_topic("points"), "rt/points");
  EXPECT_EQ(ros2_dds_topic("/cloudshape/detections"), "rt/cloudshape/detections");
  for (const char* bad : {"", "/", "/camera//points", "/camera/", "/camera/3d", "/camera points", "/a-b"}) {
    EXPECT_THROW(ros2_dds_topic(bad), DdsError) << bad;
  }
  try {
    ros2_dds_topic("/a-b");
  } catch (const DdsError& e) {
    EXPECT_THAT(e.what(), HasSubstr("ROS 2 topic '/a-b': holds '-'"));
  }
}

msg::ShapeResult object_result(const msg::CloudHeader& h, std::uint32_t index, std::uint32_t count,
                               const std::string& shape) {
  msg::ShapeResult r;
  r.header(h);
  r.header().object_index(index);
  r.header().object_count(count);
  pipeline::ObjectResult o;
  o.shape = shape;
  o.dimensions = {{"radius", 2.0}};
  r.objects().push_back(to_msg(o));
  return r;
}

TEST(Ros2Results, StampedWithTheCloudsHeaderOrItsInjectionTime) {
  config::Ros2Config cfg;
  const msg::CloudHeader ros = ros_cloud_header("/cam", kHeader, 1, 5);
  const RosResults results = ros_results({object_result(ros, 0, 2, "sphere"), object_result(ros, 1, 2, "sphere")}, cfg);
  EXPECT_EQ(results.detections.header().frame_id(), kHeader.frame_id);
  EXPECT_EQ(results.detections.header().stamp().sec(), kHeader.stamp.sec);
  EXPECT_EQ(results.detections.detections().size(), 2u);
  EXPECT_EQ(results.markers.markers().size(), 1u + 2 * 2);
  EXPECT_EQ(results.markers.markers()[0].ns(), "/cam");

  msg::CloudHeader file;
  file.source("box.pcd");
  file.inject_time_ns(1'700'000'000'123'456'789LL);
  const io::RosHeader h = ros_result_header(file, cfg);
  EXPECT_EQ(h.frame_id, "cloudshape");
  EXPECT_EQ(h.stamp.sec, 1'700'000'000);
  EXPECT_EQ(h.stamp.nanosec, 123'456'789u);
  file.inject_time_ns(-1);
  EXPECT_EQ(ros_result_header(file, cfg).stamp.sec, -1);
  EXPECT_EQ(ros_result_header(file, cfg).stamp.nanosec, 999'999'999u);
}

}  // namespace
}  // namespace cloudshape::dds
