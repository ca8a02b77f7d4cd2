// The labelled (organized) PCD writer: x y z label on a WIDTH x HEIGHT grid, NaN for empty
// pixels; every encoding reads back with its grid, its labels and float-rounded points.
#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/cloud_reader.hpp"
#include "io/cloud_writers.hpp"
#include "io/pcd_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A 3 x 2 frame with two empty pixels and labels up to the largest uint32.
const PointList kPoints = {{0.1, 0.2, 1.0},    {kNaN, kNaN, kNaN}, {-0.3, 0.25, 1.5},
                           {kNaN, kNaN, kNaN}, {0.0, -0.1, 2.0},   {1e-3, 7.0, 3.25}};
const std::vector<std::uint32_t> kLabels = {1, 0, 20, 0, 31, 4294967295u};

TEST(IoLabelledPcdWriter, HeaderDeclaresTheGridAndTheLabelField) {
  const std::string bytes = encode_labelled_pcd(kPoints, kLabels, 3, 2, PcdEncoding::ascii);
  EXPECT_EQ(
      bytes.substr(0, bytes.find("DATA")),
      "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z label\nSIZE 4 4 4 4\n"
      "TYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 3\nHEIGHT 2\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 6\n");
}

TEST(IoLabelledPcdWriter, EveryEncodingReadsBackWithGridAndLabels) {
  test::TempDir dir;
  for (const auto encoding :
       {PcdEncoding::ascii, PcdEncoding::binary, PcdEncoding::binary_compressed}) {
    const std::string path =
        dir.file("frame" + std::to_string(static_cast<int>(encoding)) + ".pcd");
    write_labelled_pcd(path, kPoints, kLabels, 3, 2, encoding);
    const CloudFile cloud = read_cloud(path);
    ASSERT_EQ(cloud.points.size(), 4u);
    EXPECT_EQ(cloud.non_finite_dropped, 2u);
    EXPECT_EQ(cloud.grid.width, 3u);
    EXPECT_EQ(cloud.grid.height, 2u);
    EXPECT_EQ(cloud.grid.pixel, (std::vector<std::uint32_t>{0, 2, 4, 5}));
    EXPECT_EQ(cloud.labels, (std::vector<std::uint32_t>{1, 20, 31, 4294967295u}));
    const std::size_t source[] = {0, 2, 4, 5};
    for (std::size_t k = 0; k < 4; ++k)
      for (int a = 0; a < 3; ++a)
        EXPECT_EQ(cloud.points[k][a],
                  static_cast<double>(static_cast<float>(kPoints[source[k]][a])));
  }
}

TEST(IoLabelledPcdWriter, ASizeMismatchIsRejected) {
  EXPECT_THROW(encode_labelled_pcd(kPoints, kLabels, 2, 2, PcdEncoding::binary),
               std::invalid_argument);
  EXPECT_THROW(encode_labelled_pcd(kPoints, {1, 2}, 3, 2, PcdEncoding::binary),
               std::invalid_argument);
}

TEST(IoLabelledPcdWriter, AnUnwritablePathIsNamed) {
  try {
    write_labelled_pcd("/nonexistent-dir/frame.pcd", kPoints, kLabels, 3, 2, PcdEncoding::binary);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/frame.pcd"), std::string::npos);
  }
}

}  // namespace
}  // namespace cloudshape::io
