// Writers against bytes written by hand from the PCD v0.7 and PLY 1.0 specifications, so a
// writer and reader that drift together (the round-trip tests) still fail here.
#include <lzf.h>

#include <fstream>
#include <iterator>

#include "io/cloud_writers.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

// Values exact in float and double, so every byte below is known without rounding.
const PointList kCloud = {Point(1.0, -2.0, 0.5), Point(0.25, 3.0, -1.0)};

std::string bytes(std::initializer_list<unsigned char> b) {
  return std::string(b.begin(), b.end());
}

// IEEE 754 little-endian: 1.0f = 3F800000, -2.0f = C0000000, 0.5f = 3F000000,
// 0.25f = 3E800000, 3.0f = 40400000, -1.0f = BF800000.
const std::string kFloatRows =
    bytes({0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0xC0, 0x00, 0x00, 0x00, 0x3F,
           0x00, 0x00, 0x80, 0x3E, 0x00, 0x00, 0x40, 0x40, 0x00, 0x00, 0x80, 0xBF});
// The same in double: 1.0 = 3FF0..., -2.0 = C000..., 0.5 = 3FE0..., 0.25 = 3FD0..., 3.0 = 4008...,
// -1.0 = BFF0...
const std::string kDoubleRows = bytes({0, 0, 0, 0, 0, 0, 0xF0, 0x3F, 0, 0, 0, 0, 0, 0, 0x00, 0xC0,
                                       0, 0, 0, 0, 0, 0, 0xE0, 0x3F, 0, 0, 0, 0, 0, 0, 0xD0, 0x3F,
                                       0, 0, 0, 0, 0, 0, 0x08, 0x40, 0, 0, 0, 0, 0, 0, 0xF0, 0xBF});
const std::string kTextRows = "1 -2 0.5\n0.25 3 -1\n";

std::string lines(std::initializer_list<std::string> each) {
  std::string out;
  for (const auto& line : each) out += line + "\n";
  return out;
}

std::string pcd_header(const std::string& size, const std::string& data,
                       const std::string& n = "2") {
  return lines({"# .PCD v0.7 - Point Cloud Data file format", "VERSION 0.7", "FIELDS x y z",
                "SIZE " + size, "TYPE F F F", "COUNT 1 1 1", "WIDTH " + n, "HEIGHT 1",
                "VIEWPOINT 0 0 0 1 0 0 0", "POINTS " + n, "DATA " + data});
}

std::string ply_header(const std::string& format, const std::string& type) {
  return lines({"ply", "format " + format + " 1.0", "comment written by cloudshape",
                "element vertex 2", "property " + type + " x", "property " + type + " y",
                "property " + type + " z", "end_header"});
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

TEST(IoWritersGolden, PcdAscii) {
  EXPECT_EQ(encode_pcd(kCloud, PcdEncoding::ascii), pcd_header("4 4 4", "ascii") + kTextRows);
  EXPECT_EQ(encode_pcd(kCloud, PcdEncoding::ascii, true), pcd_header("8 8 8", "ascii") + kTextRows);
}

TEST(IoWritersGolden, PcdBinary) {
  EXPECT_EQ(encode_pcd(kCloud, PcdEncoding::binary), pcd_header("4 4 4", "binary") + kFloatRows);
  EXPECT_EQ(encode_pcd(kCloud, PcdEncoding::binary, true),
            pcd_header("8 8 8", "binary") + kDoubleRows);
}

// binary_compressed: two little-endian uint32 (compressed size, uncompressed size), then LZF
// data of the fields one after another (all x, all y, all z). LZF may encode the same input
// more than one way, so the block is checked by its sizes and its decompressed bytes.
TEST(IoWritersGolden, PcdBinaryCompressed) {
  const std::string header = pcd_header("4 4 4", "binary_compressed");
  const std::string out = encode_pcd(kCloud, PcdEncoding::binary_compressed);
  ASSERT_GT(out.size(), header.size() + 8);
  EXPECT_EQ(out.substr(0, header.size()), header);
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(out[at + k]);
    return v;
  };
  const std::uint32_t packed = u32(header.size()), raw = u32(header.size() + 4);
  EXPECT_EQ(raw, 24u);
  EXPECT_EQ(out.size(), header.size() + 8 + packed);
  const std::string by_field =
      bytes({0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x80, 0x3E,    // x: 1, 0.25
             0x00, 0x00, 0x00, 0xC0, 0x00, 0x00, 0x40, 0x40,    // y: -2, 3
             0x00, 0x00, 0x00, 0x3F, 0x00, 0x00, 0x80, 0xBF});  // z: 0.5, -1
  std::string unpacked(64, '\0');
  const unsigned int n = lzf_decompress(out.data() + header.size() + 8, packed, unpacked.data(),
                                        static_cast<unsigned int>(unpacked.size()));
  EXPECT_EQ(unpacked.substr(0, n), by_field);
}

TEST(IoWritersGolden, Ply) {
  EXPECT_EQ(encode_ply(kCloud, false), ply_header("ascii", "float") + kTextRows);
  EXPECT_EQ(encode_ply(kCloud, true), ply_header("binary_little_endian", "float") + kFloatRows);
  EXPECT_EQ(encode_ply(kCloud, true, true),
            ply_header("binary_little_endian", "double") + kDoubleRows);
}

// Shortest text that reads back exactly: 0.1 has no exact binary form, and its float and
// double roundings print differently at full precision but both as "0.1" here.
TEST(IoWritersGolden, XyzAndShortestText) {
  EXPECT_EQ(encode_xyz(kCloud), kTextRows);
  EXPECT_EQ(encode_xyz({Point(0.1, 1e-7, 123456789.0)}), "0.1 1e-07 123456789\n");
  // As float, 0.1 is 0.100000001490116... and 123456789 is 123456792: "123456790" would
  // read back too, but is no shorter, and then the exact digits win (C++17 [charconv]).
  EXPECT_EQ(encode_pcd({Point(0.1, 1e-7, 123456789.0)}, PcdEncoding::ascii),
            pcd_header("4 4 4", "ascii", "1") + "0.1 1e-07 123456792\n");
}

TEST(IoWritersGolden, FilesHoldExactlyTheEncodedBytes) {
  test::TempDir dir;
  write_pcd(dir.file("c.pcd"), kCloud, PcdEncoding::binary);
  EXPECT_EQ(file_bytes(dir.file("c.pcd")), pcd_header("4 4 4", "binary") + kFloatRows);
  write_ply(dir.file("c.ply"), kCloud, false);
  EXPECT_EQ(file_bytes(dir.file("c.ply")), ply_header("ascii", "float") + kTextRows);
  write_xyz(dir.file("c.xyz"), kCloud);
  EXPECT_EQ(file_bytes(dir.file("c.xyz")), kTextRows);
}

}  // namespace
}  // namespace cloudshape::io
