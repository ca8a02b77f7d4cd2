// PCD reader on well-formed input: every DATA kind, field layouts, old headers, non-finite points.
// Malformed PCD input is covered in pcd_errors_test.cpp.
#include <lzf.h>

#include <limits>

#include "io/cloud_writers.hpp"
#include "io/pcd_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::append_le;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

const char* const kLabelXyzRgbaHeader =
    "# .PCD v0.7 - Point Cloud Data file format\n"
    "VERSION 0.7\n"
    "FIELDS label x y z rgba\n"
    "SIZE 4 4 4 4 4\n"
    "TYPE U F F F U\n"
    "COUNT 1 1 1 1 1\n"
    "WIDTH 3\n"
    "HEIGHT 1\n"
    "VIEWPOINT 0 0 0 1 0 0 0\n"
    "POINTS 3\n";

const PointList kThree = {{1.5, -2.25, 3.0}, {0.125, 0.0, -7.5}, {100.0, 200.0, 300.0}};

TEST(IoPcdReader, ReadsAsciiWithXyzAmongOtherFields) {
  const std::string data = std::string(kLabelXyzRgbaHeader) +
                           "DATA ascii\n"
                           "7 1.5 -2.25 3 4278190080\n"
                           "7 0.125 0 -7.5 0\n"
                           "20 100 200 300 16777215\n";
  const CloudFile cloud = read_pcd_buffer(data, "scene.pcd");
  EXPECT_EQ(cloud.format, "pcd-ascii");
  EXPECT_EQ(cloud.non_finite_dropped, 0u);
  test::expect_exact(cloud.points, kThree);
}

TEST(IoPcdReader, ReadsBinaryWithXyzAmongOtherFields) {
  std::string data = std::string(kLabelXyzRgbaHeader) + "DATA binary\n";
  for (const Point& p : kThree) {
    append_le<std::uint32_t>(data, 7);
    for (int a = 0; a < 3; ++a) append_le<float>(data, static_cast<float>(p[a]));
    append_le<std::uint32_t>(data, 0xff00ff00u);
  }
  const CloudFile cloud = read_pcd_buffer(data, "scene.pcd");
  EXPECT_EQ(cloud.format, "pcd-binary");
  test::expect_exact(cloud.points, kThree);
}

// The layout of the real mOSD files: label first, then x y z, then rgba, stored field by field.
TEST(IoPcdReader, ReadsBinaryCompressedFieldByField) {
  std::string soa;
  for (std::uint32_t label = 0; label < 3; ++label) append_le<std::uint32_t>(soa, label);
  for (int a = 0; a < 3; ++a) {
    for (const Point& p : kThree) append_le<float>(soa, static_cast<float>(p[a]));
  }
  for (int i = 0; i < 3; ++i) append_le<std::uint32_t>(soa, 0x12345678u);
  std::string packed(soa.size() * 2 + 64, '\0');
  const unsigned packed_size = lzf_compress(soa.data(), static_cast<unsigned>(soa.size()), packed.data(),
                                            static_cast<unsigned>(packed.size()));
  ASSERT_GT(packed_size, 0u);
  std::string data = std::string(kLabelXyzRgbaHeader) + "DATA binary_compressed\n";
  append_le<std::uint32_t>(data, packed_size);
  append_le<std::uint32_t>(data, static_cast<std::uint32_t>(soa.size()));
  data.append(packed.data(), packed_size);

  const CloudFile cloud = read_pcd_buffer(data, "scene.pcd");
  EXPECT_EQ(cloud.format, "pcd-binary_compressed");
  test::expect_exact(cloud.points, kThree);
}

TEST(IoPcdReader, SkipsFieldsWithCountAboveOne) {
  const std::string data =
      "VERSION 0.7\nFIELDS normal x y z curvature\nSIZE 4 4 4 8 4\nTYPE F F F F F\n"
      "COUNT 3 1 1 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n"
      "0 0 1 1.5 -2.25 3 0.5\n"
      "1 0 0 0.125 0 -7.5 0.25\n";
  const CloudFile cloud = read_pcd_buffer(data, "normals.pcd");
  test::expect_exact(cloud.points, PointList(kThree.begin(), kThree.begin() + 2));

  std::string binary =
      "VERSION 0.7\nFIELDS normal x y z\nSIZE 4 4 4 8\nTYPE F F F F\nCOUNT 3 1 1 1\n"
      "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n";
  for (int i = 0; i < 3; ++i) append_le<float>(binary, 9.0f);
  append_le<float>(binary, 1.5f);
  append_le<float>(binary, -2.25f);
  append_le<double>(binary, 3.0);
  test::expect_exact(read_pcd_buffer(binary, "normals.pcd").points, PointList{kThree[0]});
}

TEST(IoPcdReader, ReadsDoubleAndIntegerCoordinates) {
  std::string data =
      "VERSION 0.7\nFIELDS x y z\nSIZE 8 2 1\nTYPE F I U\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
      "POINTS 2\nDATA binary\n";
  append_le<double>(data, 0.1);
  append_le<std::int16_t>(data, -300);
  append_le<std::uint8_t>(data, 250);
  append_le<double>(data, -1e10);
  append_le<std::int16_t>(data, 7);
  append_le<std::uint8_t>(data, 0);
  test::expect_exact(read_pcd_buffer(data, "ints.pcd").points, PointList{{0.1, -300, 250}, {-1e10, 7, 0}});
}

TEST(IoPcdReader, ToleratesVersion6HeaderWithDefaults) {
  const std::string data =
      "# .PCD v.6 - Point Cloud Data file format\nVERSION .6\nCOLUMNS x y z\nPOINTS 2\nDATA ascii\n"
      "1.5 -2.25 3\n0.125 0 -7.5\n";
  const CloudFile cloud = read_pcd_buffer(data, "old.pcd");
  test::expect_exact(cloud.points, PointList(kThree.begin(), kThree.begin() + 2));

  std::string binary = "VERSION .6\nFIELDS x y z\nWIDTH 1\nHEIGHT 1\nDATA binary\n";
  for (float v : {1.5f, -2.25f, 3.0f}) append_le<float>(binary, v);
  test::expect_exact(read_pcd_buffer(binary, "old.pcd").points, PointList{kThree[0]});
}

TEST(IoPcdReader, AcceptsCrlfLineEndingsAndBlankDataLines) {
  const std::string data =
      "VERSION 0.7\r\nFIELDS x y z\r\nSIZE 4 4 4\r\nTYPE F F F\r\nCOUNT 1 1 1\r\nWIDTH 2\r\nHEIGHT 1\r\n"
      "POINTS 2\r\nDATA ascii\r\n1.5 -2.25 3\r\n\r\n0.125 +0 -7.5\r\n\r\n";
  test::expect_exact(read_pcd_buffer(data, "crlf.pcd").points, PointList(kThree.begin(), kThree.begin() + 2));
}

TEST(IoPcdReader, ZeroPointsIsAnEmptyCloud) {
  for (const auto encoding : {PcdEncoding::ascii, PcdEncoding::binary, PcdEncoding::binary_compressed}) {
    const CloudFile cloud = read_pcd_buffer(encode_pcd({}, encoding), "empty.pcd");
    EXPECT_TRUE(cloud.points.empty());
    EXPECT_EQ(cloud.non_finite_dropped, 0u);
  }
}

TEST(IoPcdReader, DropsAndCountsNonFinitePointsInEveryEncoding) {
  const PointList points = {{1, 2, 3}, {kNaN, 0, 0}, {4, 5, 6}, {0, kInf, 0}, {0, 0, -kInf}, {7, 8, 9}};
  for (const auto encoding : {PcdEncoding::ascii, PcdEncoding::binary, PcdEncoding::binary_compressed}) {
    for (const bool doubles : {false, true}) {
      const CloudFile cloud = read_pcd_buffer(encode_pcd(points, encoding, doubles), "nan.pcd");
      EXPECT_EQ(cloud.non_finite_dropped, 3u);
      test::expect_exact(cloud.points, PointList{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}});
    }
  }
}

TEST(IoPcdReader, AsciiAcceptsNanAndInfSpellings) {
  const std::string data =
      "FIELDS x y z\nWIDTH 4\nHEIGHT 1\nPOINTS 4\nDATA ascii\nnan 0 0\n0 -inf 0\n0 0 NaN\n1 2 3\n";
  const CloudFile cloud = read_pcd_buffer(data, "nan.pcd");
  EXPECT_EQ(cloud.non_finite_dropped, 3u);
  test::expect_exact(cloud.points, PointList{{1, 2, 3}});
}

TEST(IoPcdReader, AllNonFiniteGivesEmptyCloudNotError) {
  const PointList points(5, Point(kNaN, kNaN, kNaN));
  const CloudFile cloud = read_pcd_buffer(encode_pcd(points, PcdEncoding::binary_compressed), "void.pcd");
  EXPECT_TRUE(cloud.points.empty());
  EXPECT_EQ(cloud.non_finite_dropped, 5u);
}

TEST(IoPcdReader, OrganisedCloudUsesWidthTimesHeight) {
  std::string data =
      "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA binary\n";
  for (int i = 0; i < 12; ++i) append_le<float>(data, static_cast<float>(i));
  EXPECT_EQ(read_pcd_buffer(data, "organised.pcd").points.size(), 4u);
}

TEST(IoPcdReader, IgnoresBytesAfterTheBinaryPoints) {
  std::string data = encode_pcd(kThree, PcdEncoding::binary) + "trailing";
  EXPECT_EQ(read_pcd_buffer(data, "padded.pcd").points.size(), 3u);
}

}  // namespace
}  // namespace cloudshape::io
