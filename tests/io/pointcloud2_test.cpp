// PointCloud2 decoding: every layout the issue lists (float32 / float64 at any offset, padding,
// extra fields, either byte order, organized with NaN pixels) and every malformed layout.
#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <string>

#include "io/pointcloud2.hpp"
#include "io/pointcloud2_encode.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::expect_exact;
using test::expect_near_float;
using test::expect_read_error;
using test::sample_points;

const std::string kTopic = "/camera/depth/points";

PointCloud2 unorganized(const PointList& points, const PointCloud2Layout& layout = {}) {
  return encode_pointcloud2(points, GridLayout{}, layout, RosHeader{{12, 345}, "camera_depth_optical_frame"});
}

// 4 x 3 grid, pixels 1, 6 and 11 left out (the encoder sends them as NaN).
struct Organized {
  PointList points;
  GridLayout grid;
};
Organized organized_frame() {
  Organized o;
  o.grid.width = 4;
  o.grid.height = 3;
  const PointList all = sample_points(12);
  for (std::uint32_t pixel = 0; pixel < 12; ++pixel) {
    if (pixel == 1 || pixel == 6 || pixel == 11) continue;
    o.points.push_back(all[pixel]);
    o.grid.pixel.push_back(pixel);
  }
  return o;
}

TEST(IoPointCloud2, Float32WithRgbDecodesEveryPoint) {
  const PointList points = sample_points(100);
  const CloudFile cloud = decode_pointcloud2(unorganized(points), kTopic);
  expect_near_float(cloud.points, points);
  EXPECT_EQ(cloud.non_finite_dropped, 0u);
  EXPECT_FALSE(cloud.grid.organized());
  EXPECT_TRUE(cloud.grid.pixel.empty());
  EXPECT_EQ(cloud.format, "ros2-pointcloud2");
}

TEST(IoPointCloud2, Float64IsExact) {
  const PointList points = sample_points(50);
  expect_exact(decode_pointcloud2(unorganized(points, float64_layout()), kTopic).points, points);
}

TEST(IoPointCloud2, AnyOffsetsPointStepAndRowPadding) {
  const PointList points = sample_points(30);
  PointCloud2Layout layout = float64_layout();
  layout.offsets = {20, 4, 36};  // z last, x after rgb, nothing aligned
  layout.rgb_offset = 0;
  layout.point_step = 47;
  layout.row_padding = 13;
  const PointCloud2 msg = unorganized(points, layout);
  ASSERT_EQ(msg.row_step, 30u * 47u + 13u);
  expect_exact(decode_pointcloud2(msg, kTopic).points, points);
}

TEST(IoPointCloud2, ExtraFieldsOfEveryTypeAreIgnored) {
  const PointList points = sample_points(20);
  PointCloud2Layout layout;
  layout.point_step = 40;
  PointCloud2 msg = unorganized(points, layout);
  const std::uint8_t types[] = {1, 2, 3, 4, 5, 6, 8};
  std::uint32_t offset = 16;
  for (std::uint8_t t : types) {
    msg.fields.push_back({"extra" + std::to_string(t), offset, t, 1});
    offset += t == 8 ? 8 : 2;
  }
  msg.fields.push_back({"normal", 16, 7, 3});  // overlaps the extras: allowed, as in PCL clouds
  expect_near_float(decode_pointcloud2(msg, kTopic).points, points);
}

TEST(IoPointCloud2, BigEndianGivesTheSamePoints) {
  const PointList points = sample_points(40);
  for (PointCloud2Layout layout : {PointCloud2Layout{}, float64_layout()}) {
    const CloudFile little = decode_pointcloud2(unorganized(points, layout), kTopic);
    layout.big_endian = true;
    const PointCloud2 msg = unorganized(points, layout);
    ASSERT_TRUE(msg.is_bigendian);
    expect_exact(decode_pointcloud2(msg, kTopic).points, little.points);
  }
}

TEST(IoPointCloud2, OrganizedKeepsTheGridAndDropsNaNPixels) {
  const Organized frame = organized_frame();
  for (const PointCloud2Layout& layout : {PointCloud2Layout{}, float64_layout()}) {
    const PointCloud2 msg = encode_pointcloud2(frame.points, frame.grid, layout, {});
    ASSERT_EQ(msg.height, 3u);
    ASSERT_EQ(msg.width, 4u);
    const CloudFile cloud = decode_pointcloud2(msg, kTopic);
    EXPECT_TRUE(cloud.grid.organized());
    EXPECT_EQ(cloud.grid.width, 4u);
    EXPECT_EQ(cloud.grid.height, 3u);
    EXPECT_EQ(cloud.grid.pixel, frame.grid.pixel);
    EXPECT_EQ(cloud.non_finite_dropped, 3u);
    if (layout.coordinate == PointFieldType::float64) {
      expect_exact(cloud.points, frame.points);
    } else {
      expect_near_float(cloud.points, frame.points);
    }
  }
}

TEST(IoPointCloud2, InfiniteCoordinatesAreDroppedLikeNaN) {
  PointList points = sample_points(10);
  points[3].y() = std::numeric_limits<double>::infinity();
  points[7].z() = -std::numeric_limits<double>::infinity();
  const CloudFile cloud = decode_pointcloud2(unorganized(points, float64_layout()), kTopic);
  EXPECT_EQ(cloud.points.size(), 8u);
  EXPECT_EQ(cloud.non_finite_dropped, 2u);
  EXPECT_EQ(cloud.points[3], points[4]);
}

TEST(IoPointCloud2, EmptyCloudHasNoPoints) {
  const CloudFile cloud = decode_pointcloud2(unorganized({}), kTopic);
  EXPECT_TRUE(cloud.points.empty());
  EXPECT_EQ(cloud.non_finite_dropped, 0u);
  // No row is walked for a cloud of no column (found by fuzzing: it took minutes).
  PointCloud2 tall = unorganized({});
  tall.height = 0xffffffffu;
  tall.row_step = 0;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(decode_pointcloud2(tall, kTopic).points.empty());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

// --- Bad input: every case of issue 15 item 3, and the other ways a layout can lie. ---

void expect_error(const PointCloud2& msg, const std::string& place, const std::string& keyword,
                  const ReadLimits& limits = {}) {
  expect_read_error([&] { decode_pointcloud2(msg, kTopic, limits); }, kTopic, place, keyword);
}

TEST(IoPointCloud2Errors, MissingXYOrZIsNamed) {
  for (const char* axis : {"x", "y", "z"}) {
    PointCloud2 msg = unorganized(sample_points(5));
    for (PointField& f : msg.fields) {
      if (f.name == axis) f.name = "intensity";
    }
    expect_error(msg, "fields", std::string("no field named '") + axis + "'");
  }
  PointCloud2 none = unorganized(sample_points(5));
  none.fields.clear();
  expect_error(none, "fields", "no field named 'x' (fields: none)");
}

TEST(IoPointCloud2Errors, FieldOffsetPastPointStep) {
  PointCloud2 msg = unorganized(sample_points(5));
  msg.fields[2].offset = 14;  // z: 4 bytes from 14 end at 18 > 16
  expect_error(msg, "field 'z'", "ends at byte 18, past point_step 16");
  PointCloud2 rgb = unorganized(sample_points(5));
  rgb.fields[3].offset = 16;
  expect_error(rgb, "field 'rgb'", "ends at byte 20, past point_step 16");
}

TEST(IoPointCloud2Errors, FieldCountPastPointStep) {
  PointCloud2 msg = unorganized(sample_points(5));
  msg.fields.push_back({"normal", 8, 7, 3});  // 12 bytes from 8 end at 20 > 16
  expect_error(msg, "field 'normal'", "offset 8 + 3 x FLOAT32 ends at byte 20, past point_step 16");
  PointCloud2 huge = unorganized(sample_points(5));
  huge.fields[3].count = 0xffffffffu;  // no 32-bit wrap may hide it
  expect_error(huge, "field 'rgb'", "past point_step 16");
  PointCloud2 far = unorganized(sample_points(5));
  far.fields[0].offset = 0xfffffffeu;
  expect_error(far, "field 'x'", "past point_step 16");
}

TEST(IoPointCloud2Errors, DataShorterThanRowStepTimesHeight) {
  PointCloud2 msg = unorganized(sample_points(5));
  msg.data.resize(msg.data.size() - 1);
  expect_error(msg, "data", "79 bytes, fewer than row_step * height = 80 x 1 = 80");
  const Organized frame = organized_frame();
  PointCloud2 grid = encode_pointcloud2(frame.points, frame.grid, {}, {});
  grid.data.resize(2 * grid.row_step);  // one row short
  expect_error(grid, "data", "128 bytes, fewer than row_step * height = 64 x 3 = 192");
}

TEST(IoPointCloud2Errors, WidthTimesHeightDisagreesWithTheData) {
  PointCloud2 taller = unorganized(sample_points(6));
  taller.height = 2;  // 6 points claimed twice over: data too short
  expect_error(taller, "data", "fewer than row_step * height");
  PointCloud2 narrower = unorganized(sample_points(6));
  narrower.width = 3;  // and row_step to match: the data holds twice that
  narrower.row_step = 48;
  expect_error(narrower, "data", "96 bytes, more than row_step * height = 48 x 1 = 48");
  PointCloud2 wider = unorganized(sample_points(6));
  wider.width = 7;
  expect_error(wider, "row_step", "96 is less than width * point_step = 7 x 16 = 112");
  PointCloud2 more = unorganized(sample_points(6));
  more.data.push_back(0);
  expect_error(more, "data", "97 bytes, more than row_step * height = 96 x 1 = 96");
}

TEST(IoPointCloud2Errors, CoordinateOfAnotherTypeOrCount) {
  PointCloud2 msg = unorganized(sample_points(5));
  msg.fields[1].datatype = 3;
  expect_error(msg, "field 'y'", "is INT16; x, y and z must be FLOAT32 or FLOAT64");
  PointCloud2 counted = unorganized(sample_points(5));
  counted.fields[0].count = 2;
  expect_error(counted, "field 'x'", "count is 2; x, y and z must have count 1");
  PointCloud2 twice = unorganized(sample_points(5));
  twice.fields.push_back({"x", 12, 7, 1});
  expect_error(twice, "field 'x'", "two fields have this name");
}

TEST(IoPointCloud2Errors, UnknownDatatype) {
  PointCloud2 msg = unorganized(sample_points(5));
  msg.fields[3].datatype = 9;
  expect_error(msg, "field 'rgb'", "unknown datatype 9 (sensor_msgs/PointField defines 1..8)");
  msg.fields[3].datatype = 0;
  expect_error(msg, "field 'rgb'", "unknown datatype 0");
}

TEST(IoPointCloud2Errors, ZeroPointStep) {
  PointCloud2 msg = unorganized(sample_points(5));
  msg.point_step = 0;
  expect_error(msg, "field 'x'", "ends at byte 4, past point_step 0");
}

TEST(IoPointCloud2Errors, OverTheLimits) {
  const PointCloud2 msg = unorganized(sample_points(50));
  ReadLimits points;
  points.max_points = 49;
  expect_error(msg, "width * height", "50 x 1 = 50 points, more than the limit of 49", points);
  ReadLimits bytes;
  bytes.max_bytes = 799;
  expect_error(msg, "data", "800 bytes, more than the limit of 799", bytes);
  // A lying width is refused before anything is allocated from it.
  PointCloud2 lying = msg;
  lying.width = 0xffffffffu;
  lying.height = 0xffffffffu;
  expect_error(lying, "width * height", "more than the limit of");
}

TEST(IoPointCloud2Errors, OrganizedGridBeyondAPixelIndex) {
  PointCloud2 msg = unorganized(sample_points(5));
  msg.width = 0x10000;
  msg.height = 0x10001;
  ReadLimits unlimited;
  unlimited.max_points = std::numeric_limits<std::size_t>::max();
  expect_error(msg, "width * height", "more than a 32-bit pixel index addresses", unlimited);
}

}  // namespace
}  // namespace cloudshape::io
