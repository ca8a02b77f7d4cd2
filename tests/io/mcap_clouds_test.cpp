// PointCloud2 messages in an MCAP recording: CDR to and from the plain PointCloud2, every layout
// back to the same points, other schemas and topics skipped, a bad message reported and passed.
#include <gtest/gtest.h>

#include <sstream>

#include "io/mcap_clouds.hpp"
#include "io/mcap_writer.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/ros2_schemas.hpp"
#include "io/pointcloud2_encode.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {
using test::expect_read_error;
using test::sample_points;

PointCloud2 cloud_message(const PointList& points, const GridLayout& grid, const PointCloud2Layout& layout) {
  RosHeader header;
  header.stamp = {12, 345};
  header.frame_id = "camera_depth_optical_frame";
  return encode_pointcloud2(points, grid, layout, header);
}

TEST(IoPointCloud2Cdr, RoundTripKeepsEveryField) {
  const PointCloud2 in = cloud_message(sample_points(7), {}, float64_layout());
  const std::string bytes = pointcloud2_to_cdr(in);
  EXPECT_EQ(bytes.substr(0, 4), std::string("\x00\x01\x00\x00", 4));
  const PointCloud2 out = pointcloud2_from_cdr(bytes, "rec.mcap", "message 0");
  EXPECT_EQ(out.header.stamp.sec, 12);
  EXPECT_EQ(out.header.stamp.nanosec, 345u);
  EXPECT_EQ(out.header.frame_id, in.header.frame_id);
  EXPECT_EQ(out.height, in.height);
  EXPECT_EQ(out.width, in.width);
  ASSERT_EQ(out.fields.size(), in.fields.size());
  for (std::size_t i = 0; i < in.fields.size(); ++i) {
    EXPECT_EQ(out.fields[i].name, in.fields[i].name);
    EXPECT_EQ(out.fields[i].offset, in.fields[i].offset);
    EXPECT_EQ(out.fields[i].datatype, in.fields[i].datatype);
    EXPECT_EQ(out.fields[i].count, in.fields[i].count);
  }
  EXPECT_EQ(out.point_step, in.point_step);
  EXPECT_EQ(out.row_step, in.row_step);
  EXPECT_EQ(out.data, in.data);
  EXPECT_EQ(out.is_dense, in.is_dense);
}

// Offsets by hand for an empty-field message: the layout a ROS 2 publisher sends.
TEST(IoPointCloud2Cdr, ReadsBigEndianCdr) {
  std::string be("\x00\x00\x00\x00", 4);
  const auto u32 = [&](std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) be.push_back(static_cast<char>((v >> s) & 0xff));
  };
  u32(7);                        // sec
  u32(8);                        // nanosec
  u32(2), be += std::string("f\0", 2), be += std::string(2, '\0');  // frame_id "f", padding
  u32(1), u32(0);                // height, width
  u32(0);                        // no fields
  be.push_back(0), be += std::string(3, '\0');  // is_bigendian, padding
  u32(0), u32(0), u32(0);        // point_step, row_step, no data
  be.push_back(1);               // is_dense
  const PointCloud2 out = pointcloud2_from_cdr(be, "rec.mcap", "message 0");
  EXPECT_EQ(out.header.stamp.sec, 7);
  EXPECT_EQ(out.header.frame_id, "f");
  EXPECT_EQ(out.height, 1u);
  EXPECT_TRUE(out.is_dense);
}

TEST(IoPointCloud2Cdr, BadBytesNameTheMessageAndTheField) {
  const std::string good = pointcloud2_to_cdr(cloud_message(sample_points(5), {}, {}));
  const auto read = [](const std::string& bytes) { pointcloud2_from_cdr(bytes, "rec.mcap", "message 4"); };
  expect_read_error([&] { read(good.substr(0, 2)); }, "rec.mcap", "message 4", "encapsulation header");
  expect_read_error([&] { read(std::string("\x00\x07\x00\x00", 4) + good.substr(4)); }, "rec.mcap", "message 4",
                    "not plain CDR");
  expect_read_error([&] { read(good.substr(0, good.size() - 10)); }, "rec.mcap", "message 4",
                    "sequence 'data' claims");
  std::string lying_fields = good;
  // sec, nanosec, frame_id (4 + 27 characters + NUL), height, width: then the field count
  const std::size_t fields_at = 4 + 8 + 4 + 28 + 8;
  const std::uint32_t huge = 0x10000000u;
  std::memcpy(lying_fields.data() + fields_at, &huge, 4);
  expect_read_error([&] { read(lying_fields); }, "rec.mcap", "message 4", "sequence 'fields' claims 268435456");
  std::string no_nul = good;
  no_nul[4 + 8 + 4 + 26] = 'x';  // the NUL after "camera_depth_optical_frame"
  expect_read_error([&] { read(no_nul); }, "rec.mcap", "message 4", "not NUL-terminated");
  ReadLimits small;
  small.max_bytes = 20;
  expect_read_error([&] { pointcloud2_from_cdr(good, "rec.mcap", "message 4", small); }, "rec.mcap", "message 4",
                    "more than the limit of 20");
}

struct Layout {
  const char* name;
  PointCloud2Layout layout;
  bool organized;
  McapCompression compression;
};

class IoMcapClouds : public ::testing::TestWithParam<Layout> {};

// Every layout a recording may carry gives back the points it was made from, as the PCD
// reader would give them (float32 coordinates rounded to float, float64 exact).
TEST_P(IoMcapClouds, EveryLayoutGivesBackThePoints) {
  const PointList points = sample_points(60);
  GridLayout grid;
  if (GetParam().organized) {
    grid.width = 10;
    grid.height = 8;
    for (std::uint32_t i = 0; i < 60; ++i) grid.pixel.push_back(i + i / 3);  // holes in the grid
  }
  std::ostringstream out;
  {
    McapWriterOptions options;
    options.compression = GetParam().compression;
    McapWriter writer(out, "rec.mcap", options);
    const auto schema =
        writer.add_schema(kPointCloud2SchemaName, "ros2msg", ros2_schema_text(kPointCloud2SchemaName));
    const auto other = writer.add_schema("std_msgs/msg/String", "ros2msg", "string data\n");
    const auto cam = writer.add_channel(schema, "/camera/depth/points", "cdr");
    const auto lidar = writer.add_channel(schema, "/lidar/points", "cdr");
    const auto text = writer.add_channel(other, "/log", "cdr");
    const std::string cdr = pointcloud2_to_cdr(cloud_message(points, grid, GetParam().layout));
    writer.write(text, 1, 1, "ignored");
    writer.write(cam, 100, 100, cdr);
    writer.write(lidar, 200, 200, cdr);
    writer.write(cam, 300, 300, cdr);
  }
  std::vector<McapCloud> clouds;
  const McapCloudHandlers handlers{[&](McapCloud&& c) { clouds.push_back(std::move(c)); },
                                   [](const ReadError& e) { ADD_FAILURE() << e.what(); }};
  read_mcap_clouds_buffer(out.str(), "rec.mcap", {"/camera/depth/points"}, handlers);
  ASSERT_EQ(clouds.size(), 2u);
  EXPECT_EQ(clouds[0].index, 0u);
  EXPECT_EQ(clouds[1].index, 2u);  // the lidar's message is index 1, skipped by the topic filter
  EXPECT_EQ(clouds[1].log_time, 300u);
  EXPECT_EQ(clouds[0].header.frame_id, "camera_depth_optical_frame");
  for (const McapCloud& c : clouds) {
    if (GetParam().layout.coordinate == PointFieldType::float32) {
      test::expect_near_float(c.cloud.points, points);
    } else {
      test::expect_exact(c.cloud.points, points);
    }
    EXPECT_EQ(c.cloud.grid.organized(), GetParam().organized);
    if (GetParam().organized) {
      EXPECT_EQ(c.cloud.grid.pixel, grid.pixel);
    }
  }
}

PointCloud2Layout big_endian_padded() {
  PointCloud2Layout layout;
  layout.big_endian = true;
  layout.row_padding = 12;
  return layout;
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, IoMcapClouds,
    ::testing::Values(Layout{"float32_unorganized_zstd", {}, false, McapCompression::zstd},
                      Layout{"float32_organized_lz4", {}, true, McapCompression::lz4},
                      Layout{"float64_unorganized_lz4", float64_layout(), false, McapCompression::lz4},
                      Layout{"float64_organized_uncompressed", float64_layout(), true, McapCompression::none},
                      Layout{"big_endian_padded_rows", big_endian_padded(), true, McapCompression::zstd}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(IoMcapCloudsErrors, ABadMessageIsReportedAndTheNextOneRead) {
  std::ostringstream out;
  {
    McapWriter writer(out, "rec.mcap");
    const auto schema =
        writer.add_schema(kPointCloud2SchemaName, "ros2msg", ros2_schema_text(kPointCloud2SchemaName));
    const auto cam = writer.add_channel(schema, "/points", "cdr");
    PointCloud2 no_z = cloud_message(sample_points(5), {}, {});
    no_z.fields.erase(no_z.fields.begin() + 2);
    writer.write(cam, 1, 1, pointcloud2_to_cdr(no_z));
    writer.write(cam, 2, 2, std::string("\x00\x01\x00\x00short", 9));
    writer.write(cam, 3, 3, pointcloud2_to_cdr(cloud_message(sample_points(5), {}, {})));
  }
  std::vector<std::string> errors;
  std::size_t clouds = 0;
  read_mcap_clouds_buffer(out.str(), "rec.mcap", {},
                          {[&](McapCloud&& c) { clouds += c.cloud.points.size(); },
                           [&](const ReadError& e) { errors.push_back(e.what()); }});
  EXPECT_EQ(clouds, 5u);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_THAT(errors[0], ::testing::StartsWith("rec.mcap: message 0 (/points), fields: no field named 'z'"));
  EXPECT_THAT(errors[1], ::testing::StartsWith("rec.mcap: message 1 (/points): CDR: field"));
}

TEST(IoMcapClouds, RecognisesTheExtension) {
  EXPECT_TRUE(is_mcap_path("run/rosbag2_2024_05_01-10_00_00_0.MCAP"));
  EXPECT_FALSE(is_mcap_path("box.pcd"));
}


TEST(IoMcapClouds, ReadsOneMessageAgainByItsIndex) {
  const test::TempDir dir;
  const std::string path = dir.file("rec.mcap");
  {
    McapWriter writer(path);
    const auto schema =
        writer.add_schema(kPointCloud2SchemaName, "ros2msg", ros2_schema_text(kPointCloud2SchemaName));
    const auto cam = writer.add_channel(schema, "/points", "cdr");
    for (std::size_t n : {5, 6, 7}) writer.write(cam, n, n, pointcloud2_to_cdr(cloud_message(sample_points(n), {}, {})));
  }
  const McapCloud second = read_mcap_cloud_at(path, 1);
  EXPECT_EQ(second.index, 1u);
  EXPECT_EQ(second.cloud.points.size(), 6u);
  EXPECT_EQ(second.log_time, 6u);
  expect_read_error([&] { read_mcap_cloud_at(path, 3); }, path, "message 3",
                    "no such PointCloud2 message (the recording holds 3)");
}

// --start: message N keeps its number (FILE.mcap#N), other topics do not count, and a cloud
// start in seconds counts from the recording's first log time.
TEST(IoMcapClouds, StartsAtAMessageOrATimeKeepingTheNumbers) {
  for (const bool indexed : {true, false}) {
    SCOPED_TRACE(indexed ? "indexed" : "without indexes");
    std::ostringstream out;
    {
      McapWriterOptions options;
      options.chunk_size = 1;
      options.indexed = indexed;
      McapWriter writer(out, "rec.mcap", options);
      const auto schema =
          writer.add_schema(kPointCloud2SchemaName, "ros2msg", ros2_schema_text(kPointCloud2SchemaName));
      const auto cam = writer.add_channel(schema, "/points", "cdr");
      const auto log = writer.add_channel(0, "/rosout", "json");
      for (std::size_t n = 0; n < 8; ++n) {
        writer.write(log, 100 * n, 0, "{}");
        writer.write(cam, 100 * n + 50, 0, pointcloud2_to_cdr(cloud_message(sample_points(n + 3), {}, {})));
      }
    }
    const auto indexes = [&](const McapCloudStart& start) {
      std::vector<std::size_t> got;
      const McapReadSummary read = read_mcap_clouds_buffer(out.str(), "rec.mcap", {},
                                                           {[&](McapCloud&& c) {
                                                              EXPECT_EQ(c.cloud.points.size(), c.index + 3);
                                                              got.push_back(c.index);
                                                            },
                                                            [](const ReadError& e) { ADD_FAILURE() << e.what(); }},
                                                           {}, start);
      EXPECT_EQ(read.index_used, indexed && !start.at_beginning());
      return got;
    };
    using V = std::vector<std::size_t>;
    EXPECT_EQ(indexes(parse_mcap_start("5")), (V{5, 6, 7}));
    EXPECT_EQ(indexes(parse_mcap_start("8")), V{});
    // 0.000000451 s = 451 ns after the first message (0): clouds logged at 550 and later.
    EXPECT_EQ(indexes(parse_mcap_start("0.000000451s")), (V{5, 6, 7}));
    EXPECT_EQ(indexes(parse_mcap_start("0s")), (V{0, 1, 2, 3, 4, 5, 6, 7}));
  }
}

TEST(IoMcapClouds, ABadStartSaysWhatIsExpected) {
  for (const char* bad : {"", "-1", "1.5", "s", "2.5ms", "1e3s", "1.2.3s", "99999999999999999999999", "99999999999s"}) {
    SCOPED_TRACE(bad);
    try {
      parse_mcap_start(bad);
      ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "--start '" + std::string(bad) +
                                           "': expected a message index (e.g. 150) or seconds into the recording "
                                           "(e.g. 2.5s)");
    }
  }
  EXPECT_EQ(parse_mcap_start("150").message, 150u);
  EXPECT_EQ(parse_mcap_start("2.5s").after_ns, 2500000000u);
}

}  // namespace
}  // namespace cloudshape::io
