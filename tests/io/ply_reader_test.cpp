// PLY point-cloud reader: ascii and binary_little_endian, any property order, extra elements
// and list properties skipped, non-finite vertices dropped, and every malformed-input error.
#include <limits>

#include "io/cloud_writers.hpp"
#include "io/ply_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::append_le;
using test::expect_read_error;

CloudFile read(const std::string& data, const ReadLimits& limits = {}) {
  return read_ply_buffer(data, "ball.ply", limits);
}

const PointList kTwo = {{1.5, -2.25, 3.0}, {0.125, 0.0, -7.5}};

TEST(IoPlyReader, AsciiWithShuffledPropertiesListsAndOtherElements) {
  const std::string data =
      "ply\n"
      "format ascii 1.0\n"
      "comment exported by a scanner\n"
      "obj_info anything\n"
      "element camera 1\n"
      "property float view_x\n"
      "property list uchar int tags\n"
      "element vertex 2\n"
      "property uchar red\n"
      "property double z\n"
      "property list uint8 float weights\n"
      "property float y\n"
      "property float x\n"
      "element face 1\n"
      "property list uchar int vertex_indices\n"
      "end_header\n"
      "0.5 3 1 2 3\n"
      "255 3 2 0.1 0.2 -2.25 1.5\n"
      "0 -7.5 0 0 0.125\n"
      "3 0 1 0\n";
  const CloudFile cloud = read(data);
  EXPECT_EQ(cloud.format, "ply-ascii");
  test::expect_exact(cloud.points, kTwo);
}

TEST(IoPlyReader, BinaryWithElementBeforeVertexAndMixedTypes) {
  std::string data =
      "ply\nformat binary_little_endian 1.0\n"
      "element material 2\nproperty list ushort uchar name\nproperty short id\n"
      "element vertex 2\nproperty char flag\nproperty float x\nproperty list int double extra\n"
      "property double y\nproperty int16 z\n"
      "element face 1\nproperty list uchar uint vertex_indices\n"
      "end_header\n";
  append_le<std::uint16_t>(data, 3);
  data += "abc";
  append_le<std::int16_t>(data, 1);
  append_le<std::uint16_t>(data, 0);
  append_le<std::int16_t>(data, 2);
  append_le<std::int8_t>(data, -1);
  append_le<float>(data, 1.5f);
  append_le<std::int32_t>(data, 2);
  append_le<double>(data, 9.0);
  append_le<double>(data, 9.0);
  append_le<double>(data, -2.25);
  append_le<std::int16_t>(data, 3);
  append_le<std::int8_t>(data, 0);
  append_le<float>(data, 0.125f);
  append_le<std::int32_t>(data, 0);
  append_le<double>(data, 0.0);
  append_le<std::int16_t>(data, -7);
  // The face element after the vertices is deliberately cut short: it must not be read.
  data += "\x03";
  const CloudFile cloud = read(data);
  EXPECT_EQ(cloud.format, "ply-binary_little_endian");
  test::expect_exact(cloud.points, PointList{{1.5, -2.25, 3.0}, {0.125, 0.0, -7.0}});
}

TEST(IoPlyReader, RoundTripsThroughWriter) {
  const PointList points = test::sample_points(321);
  for (const bool binary : {false, true}) {
    test::expect_near_float(read(encode_ply(points, binary)).points, points);
    test::expect_exact(read(encode_ply(points, binary, /*double_precision=*/true)).points, points);
  }
}

TEST(IoPlyReader, DropsAndCountsNonFiniteVertices) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PointList points = {{1, 2, 3}, {nan, 0, 0}, {0, 0, std::numeric_limits<double>::infinity()}, {4, 5, 6}};
  for (const bool binary : {false, true}) {
    const CloudFile cloud = read(encode_ply(points, binary));
    EXPECT_EQ(cloud.non_finite_dropped, 2u);
    test::expect_exact(cloud.points, PointList{{1, 2, 3}, {4, 5, 6}});
  }
  const CloudFile all_bad = read(encode_ply(PointList(3, Point(nan, 1, 1)), true));
  EXPECT_TRUE(all_bad.points.empty());
  EXPECT_EQ(all_bad.non_finite_dropped, 3u);
}

TEST(IoPlyReader, ZeroPropertyElementWithHugeCountCostsNothing) {
  std::string data =
      "ply\nformat binary_little_endian 1.0\nelement nothing 18446744073709551615\n"
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  for (float v : {1.5f, -2.25f, 3.0f}) append_le<float>(data, v);
  test::expect_exact(read(data).points, PointList{kTwo[0]});
}

TEST(IoPlyReader, CrlfHeaderAndBlankLines) {
  const std::string data =
      "ply\r\nformat ascii 1.0\r\nelement vertex 2\r\nproperty float x\r\nproperty float y\r\n"
      "property float z\r\nend_header\r\n1.5 -2.25 3\r\n\r\n0.125 0 -7.5\r\n";
  test::expect_exact(read(data).points, kTwo);
}

// --- malformed input -------------------------------------------------------------------------

const char* const kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
    "end_header\n";

TEST(IoPlyErrors, EmptyInput) { expect_read_error([] { read(""); }, "ball.ply", "byte 0", "empty file"); }

TEST(IoPlyErrors, NotAPlyFile) {
  expect_read_error([] { read("VERSION 0.7\n"); }, "ball.ply", "line 1", "not a PLY file");
  expect_read_error([] { read("ply\nformat ascii 1.0\nelement vertex 1\n"); }, "ball.ply", "header",
                    "no end_header");
  expect_read_error([] { read("ply\nelement vertex 0\nend_header\n"); }, "ball.ply", "header", "no format line");
}

TEST(IoPlyErrors, BigEndianIsUnsupported) {
  expect_read_error([] { read("ply\nformat binary_big_endian 1.0\nelement vertex 0\nend_header\n"); }, "ball.ply",
                    "line 2", "unsupported format binary_big_endian");
}

TEST(IoPlyErrors, MalformedDeclarations) {
  expect_read_error([] { read("ply\nformat ascii 1.0\nproperty float x\nend_header\n"); }, "ball.ply", "line 3",
                    "property before any element");
  expect_read_error([] { read("ply\nformat ascii 1.0\nelement vertex 1\nproperty half x\nend_header\n"); },
                    "ball.ply", "line 4", "unknown property type 'half'");
  expect_read_error([] { read("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n"); }, "ball.ply", "line 3",
                    "non-negative integer count");
  expect_read_error([] { read("ply\nformat ascii 1.0\nelement f 1\nproperty list float int i\nend_header\n"); },
                    "ball.ply", "line 4", "not an integer type");
  expect_read_error([] { read("ply\nformat ascii 1.0\nmystery\nend_header\n"); }, "ball.ply", "line 3",
                    "unknown header keyword 'mystery'");
}

TEST(IoPlyErrors, MissingVertexElementOrCoordinate) {
  expect_read_error([] { read("ply\nformat ascii 1.0\nelement face 0\nend_header\n"); }, "ball.ply", "header",
                    "missing element 'vertex'");
  expect_read_error(
      [] { read("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float z\nend_header\n1 2\n"); },
      "ball.ply", "line 3", "missing property 'y'");
}

TEST(IoPlyErrors, VertexCountAboveLimit) {
  ReadLimits limits;
  limits.max_points = 10;
  expect_read_error(
      [&] {
        read("ply\nformat binary_little_endian 1.0\nelement vertex 11\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n",
             limits);
      },
      "ball.ply", "line 3", "more than the limit of 10");
}

TEST(IoPlyErrors, FewerAsciiRowsThanDeclared) {
  expect_read_error([] { read(std::string(kAsciiHeader) + "1 2 3\n"); }, "ball.ply", "line 9",
                    "header/data count mismatch: element 'vertex' declares 2 records, found 1");
}

TEST(IoPlyErrors, NonNumericAndMiscountedAsciiValues) {
  expect_read_error([] { read(std::string(kAsciiHeader) + "1 2 3\n4 y 6\n"); }, "ball.ply", "line 9",
                    "non-numeric value 'y' for property 'y'");
  expect_read_error([] { read(std::string(kAsciiHeader) + "1 2\n4 5 6\n"); }, "ball.ply", "line 8", "too few values");
  expect_read_error([] { read(std::string(kAsciiHeader) + "1 2 3 4\n4 5 6\n"); }, "ball.ply", "line 8",
                    "too many values");
}

TEST(IoPlyErrors, TruncatedBinaryVertices) {
  const std::string full = encode_ply(test::sample_points(10), true);
  const std::string cut = full.substr(0, full.size() - 1);
  expect_read_error([&] { read(cut); }, "ball.ply", "byte " + std::to_string(cut.size()),
                    "truncated binary data in element 'vertex' (expected 120 bytes, found 119)");
}

TEST(IoPlyErrors, HugeListBeforeVertexIsTruncationNotAHang) {
  std::string data =
      "ply\nformat binary_little_endian 1.0\nelement blob 1000000000\nproperty list uint uchar bytes\n"
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  append_le<std::uint32_t>(data, 4000000000u);
  data += "xyz";
  expect_read_error([&] { read(data); }, "ball.ply", "byte " + std::to_string(data.size()),
                    "truncated binary data in element 'blob' (record 0 of 1000000000)");
}

TEST(IoPlyErrors, NegativeBinaryListLength) {
  std::string data =
      "ply\nformat binary_little_endian 1.0\nelement blob 1\nproperty list char uchar bytes\n"
      "element vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  const std::size_t at = data.size();
  append_le<std::int8_t>(data, -3);
  expect_read_error([&] { read(data); }, "ball.ply", "byte " + std::to_string(at), "negative list length");
}

}  // namespace
}  // namespace cloudshape::io
