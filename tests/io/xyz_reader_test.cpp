// XYZ/TXT reader: separators, extra columns, comments and blank lines, non-finite values, and
// errors that name the offending line.
#include <limits>

#include "io/cloud_writers.hpp"
#include "io/xyz_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::expect_read_error;

CloudFile read(const std::string& data, const ReadLimits& limits = {}) {
  return read_xyz_buffer(data, "scan.xyz", limits);
}

TEST(IoXyzReader, SpacesTabsCommasExtraColumnsCommentsAndBlankLines) {
  const std::string data =
      "# x y z intensity\n"
      "1.5 -2.25 3\n"
      "\n"
      "0.125\t0\t-7.5\t42\n"
      "   # indented comment\n"
      "1e2,2e2, 3e2 ,label\r\n"
      "   \t  \n"
      "+4 -0 .5";
  const CloudFile cloud = read(data);
  EXPECT_EQ(cloud.format, "xyz");
  test::expect_exact(cloud.points, PointList{{1.5, -2.25, 3}, {0.125, 0, -7.5}, {100, 200, 300}, {4, 0, 0.5}});
}

TEST(IoXyzReader, SkipsUtf8ByteOrderMark) {
  test::expect_exact(read("\xEF\xBB\xBF" "1 2 3\n").points, PointList{{1, 2, 3}});
}

TEST(IoXyzReader, DropsAndCountsNonFinite) {
  const CloudFile cloud = read("1 2 3\nnan 0 0\n0 inf 0\n0 0 -infinity\n4 5 6\n1e999 0 0\n");
  EXPECT_EQ(cloud.non_finite_dropped, 4u);
  test::expect_exact(cloud.points, PointList{{1, 2, 3}, {4, 5, 6}});
  const CloudFile all_bad = read("nan nan nan\n");
  EXPECT_TRUE(all_bad.points.empty());
  EXPECT_EQ(all_bad.non_finite_dropped, 1u);
}

TEST(IoXyzReader, UnderflowReadsAsZero) {
  test::expect_exact(read("1e-400 -1e-400 0.0000001e-330\n").points, PointList{{0, 0, 0}});
}

TEST(IoXyzReader, OnlyCommentsGiveAnEmptyCloud) {
  const CloudFile cloud = read("# nothing measured\n\n");
  EXPECT_TRUE(cloud.points.empty());
  EXPECT_EQ(cloud.non_finite_dropped, 0u);
}

TEST(IoXyzReader, RoundTripsThroughWriterExactly) {
  const PointList points = test::sample_points(500);
  test::expect_exact(read(encode_xyz(points)).points, points);
  EXPECT_TRUE(read(encode_xyz({})).points.empty());
}

TEST(IoXyzErrors, EmptyInput) { expect_read_error([] { read(""); }, "scan.xyz", "byte 0", "empty file"); }

TEST(IoXyzErrors, NonNumericValueNamesTheLine) {
  expect_read_error([] { read("1 2 3\n\n4 5 six\n"); }, "scan.xyz", "line 3", "non-numeric value 'six' in column 3");
  expect_read_error([] { read("X Y Z\n1 2 3\n"); }, "scan.xyz", "line 1", "non-numeric value 'X'");
  expect_read_error([] { read("1 2 3.0.0\n"); }, "scan.xyz", "line 1", "non-numeric");
}

TEST(IoXyzErrors, FewerThanThreeValues) {
  expect_read_error([] { read("1 2 3\n4 5\n"); }, "scan.xyz", "line 2", "too few values");
}

TEST(IoXyzErrors, MorePointsThanLimit) {
  ReadLimits limits;
  limits.max_points = 2;
  expect_read_error([&] { read("1 2 3\n4 5 6\nnan 0 0\n", limits); }, "scan.xyz", "line 3",
                    "more than the limit of 2 points");
}

TEST(IoXyzErrors, InputLargerThanByteLimit) {
  ReadLimits limits;
  limits.max_bytes = 4;
  expect_read_error([&] { read("1 2 3\n", limits); }, "scan.xyz", "byte 4", "limit");
}

}  // namespace
}  // namespace cloudshape::io
