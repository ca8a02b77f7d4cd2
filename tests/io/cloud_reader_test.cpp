// read_cloud: format chosen by extension, file-level failures (missing, empty, too large,
// directory, unknown extension), and the file path in every message.
#include "io/cloud_reader.hpp"
#include "io/cloud_writers.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::expect_read_error;

TEST(IoCloudReader, DispatchesOnExtensionCaseInsensitively) {
  test::TempDir dir;
  const PointList points = test::sample_points(10);
  write_pcd(dir.file("a.PCD"), points, PcdEncoding::binary);
  write_ply(dir.file("b.Ply"), points, false);
  write_xyz(dir.file("c.XYZ"), points);
  write_xyz(dir.file("d.txt"), points);
  EXPECT_EQ(read_cloud(dir.file("a.PCD")).format, "pcd-binary");
  EXPECT_EQ(read_cloud(dir.file("b.Ply")).format, "ply-ascii");
  EXPECT_EQ(read_cloud(dir.file("c.XYZ")).format, "xyz");
  EXPECT_EQ(read_cloud(dir.file("d.txt")).points.size(), 10u);
}

TEST(IoCloudReader, PerFormatFileReadersIgnoreTheExtension) {
  test::TempDir dir;
  const PointList points = test::sample_points(5);
  const std::string pcd = dir.write("scan.dat", encode_pcd(points, PcdEncoding::ascii));
  const std::string ply = dir.write("scan.bin", encode_ply(points, true));
  const std::string xyz = dir.write("scan.csv", encode_xyz(points));
  EXPECT_EQ(read_pcd_file(pcd).format, "pcd-ascii");
  EXPECT_EQ(read_ply_file(ply).format, "ply-binary_little_endian");
  test::expect_exact(read_xyz_file(xyz).points, points);
  expect_read_error([&] { read_pcd_file(xyz); }, xyz, "line 1", "unknown header keyword");
}

TEST(IoCloudReader, UnknownExtension) {
  test::TempDir dir;
  const std::string path = dir.write("cloud.las", "1 2 3\n");
  expect_read_error([&] { read_cloud(path); }, path, "file name", "unknown extension '.las'");
  const std::string bare = dir.write("cloud", "1 2 3\n");
  expect_read_error([&] { read_cloud(bare); }, bare, "file name", "unknown extension");
}

TEST(IoCloudReader, MissingFileAndDirectory) {
  test::TempDir dir;
  const std::string missing = dir.file("absent.pcd");
  expect_read_error([&] { read_cloud(missing); }, missing, "open", "No such file");
  const std::string folder = dir.file("folder.xyz");
  std::filesystem::create_directory(folder);
  expect_read_error([&] { read_cloud(folder); }, folder, "open", "directory");
}

TEST(IoCloudReader, EmptyFile) {
  test::TempDir dir;
  for (const char* name : {"e.pcd", "e.ply", "e.xyz"}) {
    const std::string path = dir.write(name, "");
    expect_read_error([&] { read_cloud(path); }, path, "byte 0", "empty file");
  }
}

TEST(IoCloudReader, FileLargerThanByteLimitIsRejectedBeforeReading) {
  test::TempDir dir;
  const std::string path = dir.write("big.xyz", std::string(5000, '1'));
  ReadLimits limits;
  limits.max_bytes = 4096;
  expect_read_error([&] { read_cloud(path, limits); }, path, "byte 4096", "more than the limit of 4096 bytes");
}

TEST(IoCloudReader, ErrorsFromTheFormatReaderNameThePath) {
  test::TempDir dir;
  const std::string path = dir.write("bad.xyz", "1 2 3\n1 2 oops\n");
  expect_read_error([&] { read_cloud(path); }, path, "line 2", "non-numeric");
}

}  // namespace
}  // namespace cloudshape::io
