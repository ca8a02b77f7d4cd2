// PCD reader on organized clouds: the pixel of every kept point, the grid's size, and the
// "label" field kept as per-point ground truth (the layout of real Kinect frames).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "io/pcd_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::append_le;

std::string organized_header(const std::string& data_kind) {
  return "VERSION 0.7\n"
         "FIELDS label x y z\n"
         "SIZE 4 4 4 4\n"
         "TYPE U F F F\n"
         "COUNT 1 1 1 1\n"
         "WIDTH 3\n"
         "HEIGHT 2\n"
         "POINTS 6\n"
         "DATA " + data_kind + "\n";
}

// Row-major 3 x 2 grid; pixels 1 and 5 are invalid (NaN), as a depth camera leaves them.
const char* const kAsciiRows =
    "1 0 0 1\n"
    "0 nan nan nan\n"
    "20 2 0 1\n"
    "21 0 1 1\n"
    "30 1 1 1\n"
    "0 nan nan nan\n";

TEST(IoPcdOrganized, AsciiKeepsGridPixelsAndLabels) {
  const CloudFile cloud = read_pcd_buffer(organized_header("ascii") + kAsciiRows, "frame.pcd");
  ASSERT_EQ(cloud.points.size(), 4u);
  EXPECT_EQ(cloud.non_finite_dropped, 2u);
  EXPECT_EQ(cloud.grid.width, 3u);
  EXPECT_EQ(cloud.grid.height, 2u);
  EXPECT_TRUE(cloud.grid.organized());
  EXPECT_EQ(cloud.grid.pixel, (std::vector<std::uint32_t>{0, 2, 3, 4}));
  EXPECT_EQ(cloud.labels, (std::vector<std::uint32_t>{1, 20, 21, 30}));
  EXPECT_EQ(cloud.points[1], Point(2, 0, 1));
}

TEST(IoPcdOrganized, BinaryMatchesAscii) {
  std::string data = organized_header("binary");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float rows[6][4] = {{1, 0, 0, 1}, {0, nan, nan, nan}, {20, 2, 0, 1},
                            {21, 0, 1, 1}, {30, 1, 1, 1},     {0, nan, nan, nan}};
  for (const auto& r : rows) {
    append_le<std::uint32_t>(data, static_cast<std::uint32_t>(r[0] == r[0] ? r[0] : 0));
    for (int a = 1; a < 4; ++a) append_le<float>(data, r[a]);
  }
  const CloudFile binary = read_pcd_buffer(data, "frame.pcd");
  const CloudFile ascii = read_pcd_buffer(organized_header("ascii") + kAsciiRows, "frame.pcd");
  EXPECT_EQ(binary.grid.pixel, ascii.grid.pixel);
  EXPECT_EQ(binary.labels, ascii.labels);
  test::expect_exact(binary.points, ascii.points);
}

TEST(IoPcdOrganized, OneRowIsUnorganizedAndUnlabelledFilesHaveNoLabels) {
  const std::string data =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
      "POINTS 2\nDATA ascii\n0 0 0\n1 1 1\n";
  const CloudFile cloud = read_pcd_buffer(data, "row.pcd");
  EXPECT_FALSE(cloud.grid.organized());
  EXPECT_TRUE(cloud.grid.pixel.empty());
  EXPECT_TRUE(cloud.labels.empty());
}

}  // namespace
}  // namespace cloudshape::io
