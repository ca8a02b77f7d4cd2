// Writers: every format and encoding reads back through read_cloud (float files equal to the
// float-rounded input, double files exactly), and failures name the path.
#include <limits>

#include "io/cloud_reader.hpp"
#include "io/cloud_writers.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

struct Encoding {
  PcdEncoding pcd;
  const char* format;
};

const Encoding kPcdEncodings[] = {{PcdEncoding::ascii, "pcd-ascii"},
                                  {PcdEncoding::binary, "pcd-binary"},
                                  {PcdEncoding::binary_compressed, "pcd-binary_compressed"}};

TEST(IoWriters, PcdRoundTripsInEveryEncoding) {
  test::TempDir dir;
  const PointList points = test::sample_points(1000);
  for (const auto& e : kPcdEncodings) {
    const std::string path = dir.file(std::string(e.format) + ".pcd");
    write_pcd(path, points, e.pcd);
    const CloudFile cloud = read_cloud(path);
    EXPECT_EQ(cloud.format, e.format);
    test::expect_near_float(cloud.points, points);

    write_pcd(path, points, e.pcd, /*double_precision=*/true);
    test::expect_exact(read_cloud(path).points, points);
  }
}

TEST(IoWriters, PlyRoundTripsAsciiAndBinary) {
  test::TempDir dir;
  const PointList points = test::sample_points(1000);
  for (const bool binary : {false, true}) {
    const std::string path = dir.file(binary ? "b.ply" : "a.ply");
    write_ply(path, points, binary);
    const CloudFile cloud = read_cloud(path);
    EXPECT_EQ(cloud.format, binary ? "ply-binary_little_endian" : "ply-ascii");
    test::expect_near_float(cloud.points, points);
    write_ply(path, points, binary, /*double_precision=*/true);
    test::expect_exact(read_cloud(path).points, points);
  }
}

TEST(IoWriters, XyzRoundTripsExactly) {
  test::TempDir dir;
  const PointList points = test::sample_points(1000);
  write_xyz(dir.file("p.xyz"), points);
  test::expect_exact(read_cloud(dir.file("p.xyz")).points, points);
}

TEST(IoWriters, EmptyCloudRoundTripsInEveryFormat) {
  test::TempDir dir;
  for (const auto& e : kPcdEncodings) {
    write_pcd(dir.file("e.pcd"), {}, e.pcd);
    EXPECT_TRUE(read_cloud(dir.file("e.pcd")).points.empty());
  }
  for (const bool binary : {false, true}) {
    write_ply(dir.file("e.ply"), {}, binary);
    EXPECT_TRUE(read_cloud(dir.file("e.ply")).points.empty());
  }
  write_xyz(dir.file("e.xyz"), {});
  EXPECT_TRUE(read_cloud(dir.file("e.xyz")).points.empty());
}

TEST(IoWriters, ExtremeValuesSurviveDoublePrecision) {
  test::TempDir dir;
  const PointList points = {{std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(), -0.0},
                            {1e-300, -1e300, 0.1}};
  write_pcd(dir.file("x.pcd"), points, PcdEncoding::ascii, true);
  test::expect_exact(read_cloud(dir.file("x.pcd")).points, points);
  write_xyz(dir.file("x.xyz"), points);
  test::expect_exact(read_cloud(dir.file("x.xyz")).points, points);
}

TEST(IoWriters, FailureNamesThePath) {
  test::TempDir dir;
  const std::string path = dir.file("no/such/dir/out.pcd");
  const PointList points = test::sample_points(3);
  for (const auto& write : std::initializer_list<std::function<void()>>{
           [&] { write_pcd(path, points, PcdEncoding::binary); }, [&] { write_ply(path, points, true); },
           [&] { write_xyz(path, points); }}) {
    try {
      write();
      ADD_FAILURE() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr(path));
    }
  }
}

}  // namespace
}  // namespace cloudshape::io
