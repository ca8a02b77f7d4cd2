// PCD reader on malformed input: each failure must be a one-line ReadError naming the file,
// the place (line or byte) and the problem, and must never allocate from an unchecked header.
#include <lzf.h>

#include "io/cloud_writers.hpp"
#include "io/pcd_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using test::append_le;
using test::expect_read_error;

// Line numbers below refer to this layout: header lines 1-9, data from line 10.
std::string header(const std::string& fields = "x y z", const std::string& size = "4 4 4",
                   const std::string& type = "F F F", const std::string& count = "1 1 1",
                   const std::string& width = "2", const std::string& points = "2",
                   const std::string& data = "ascii") {
  return "VERSION 0.7\nFIELDS " + fields + "\nSIZE " + size + "\nTYPE " + type + "\nCOUNT " + count +
         "\nWIDTH " + width + "\nHEIGHT 1\nPOINTS " + points + "\nDATA " + data + "\n";
}

CloudFile read(const std::string& data, const ReadLimits& limits = {}) {
  return read_pcd_buffer(data, "box.pcd", limits);
}

TEST(IoPcdErrors, EmptyInput) {
  expect_read_error([] { read(""); }, "box.pcd", "byte 0", "empty file");
}

TEST(IoPcdErrors, MissingCoordinateField) {
  expect_read_error([] { read(header("x y rgb", "4 4 4", "F F U") + "1 2 3\n4 5 6\n"); }, "box.pcd", "line 2",
                    "missing field 'z'");
}

TEST(IoPcdErrors, PointsDisagreesWithWidthTimesHeight) {
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F", "1 1 1", "2", "3") + "1 2 3\n4 5 6\n"); },
                    "box.pcd", "header", "header/data count mismatch");
}

TEST(IoPcdErrors, FewerAsciiRowsThanDeclared) {
  expect_read_error([] { read(header() + "1 2 3\n"); }, "box.pcd", "line 11", "count mismatch");
}

TEST(IoPcdErrors, MoreAsciiRowsThanDeclared) {
  expect_read_error([] { read(header() + "1 2 3\n4 5 6\n7 8 9\n"); }, "box.pcd", "line 12", "count mismatch");
}

TEST(IoPcdErrors, NonNumericAsciiValue) {
  expect_read_error([] { read(header() + "1 2 3\n4 five 6\n"); }, "box.pcd", "line 11", "non-numeric value 'five'");
  expect_read_error([] { read(header() + "1 2 3\n4 5 6x\n"); }, "box.pcd", "line 11", "non-numeric");
}

TEST(IoPcdErrors, WrongNumberOfAsciiValues) {
  expect_read_error([] { read(header() + "1 2\n4 5 6\n"); }, "box.pcd", "line 10", "too few values");
  expect_read_error([] { read(header() + "1 2 3\n4 5 6 7\n"); }, "box.pcd", "line 11", "too many values");
}

TEST(IoPcdErrors, UnknownDataKind) {
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F", "1 1 1", "2", "2", "binary_zstd")); }, "box.pcd",
                    "line 9", "unknown DATA kind 'binary_zstd'");
}

TEST(IoPcdErrors, TruncatedBinaryData) {
  const std::string full = encode_pcd(test::sample_points(10), PcdEncoding::binary);
  const std::string cut = full.substr(0, full.size() - 7);
  expect_read_error([&] { read(cut); }, "box.pcd", "byte " + std::to_string(cut.size()),
                    "truncated binary data (expected 120 bytes of points, found 113)");
}

TEST(IoPcdErrors, TruncatedCompressedData) {
  const std::string full = encode_pcd(test::sample_points(50), PcdEncoding::binary_compressed);
  const std::string cut = full.substr(0, full.size() - 5);
  expect_read_error([&] { read(cut); }, "box.pcd", "byte " + std::to_string(cut.size()), "truncated compressed data");
  const std::size_t data_start = full.find("DATA binary_compressed\n") + 23;
  expect_read_error([&] { read(full.substr(0, data_start + 5)); }, "box.pcd",
                    "byte " + std::to_string(data_start + 5), "missing the 8-byte size prefix");
}

TEST(IoPcdErrors, CorruptLzfStream) {
  std::string data = encode_pcd(test::sample_points(200), PcdEncoding::binary_compressed);
  const std::size_t data_start = data.find("DATA binary_compressed\n") + 23;
  // A back reference pointing before the start of the output is invalid in any position.
  data[data_start + 8] = static_cast<char>(0xE0);
  data[data_start + 9] = static_cast<char>(0x00);
  data[data_start + 10] = static_cast<char>(0xFF);
  expect_read_error([&] { read(data); }, "box.pcd", "byte " + std::to_string(data_start + 8), "corrupt LZF stream");
}

TEST(IoPcdErrors, CompressedBlockSizeDisagreesWithHeader) {
  std::string data = encode_pcd(test::sample_points(20), PcdEncoding::binary_compressed);
  const std::size_t data_start = data.find("DATA binary_compressed\n") + 23;
  data[data_start + 4] = static_cast<char>(data[data_start + 4] + 12);
  expect_read_error([&] { read(data); }, "box.pcd", "byte " + std::to_string(data_start + 4), "size mismatch");
}

TEST(IoPcdErrors, CompressedBlockThatCannotExpandToDeclaredSizeIsRejectedBeforeAllocating) {
  // 40 million points would need a 480 MB buffer; 16 compressed bytes cannot hold them.
  std::string data = header("x y z", "4 4 4", "F F F", "1 1 1", "40000000", "40000000", "binary_compressed");
  append_le<std::uint32_t>(data, 16);
  append_le<std::uint32_t>(data, 480000000u);
  data.append(16, '\xE0');
  expect_read_error([&] { read(data); }, "box.pcd", "byte " + std::to_string(data.size() - 16), "corrupt LZF stream");
}

TEST(IoPcdErrors, DeclaredPointCountAboveLimit) {
  ReadLimits limits;
  limits.max_points = 1000;
  expect_read_error([&] { read(header("x y z", "4 4 4", "F F F", "1 1 1", "1001", "1001"), limits); }, "box.pcd",
                    "header", "more than the limit of 1000");
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F", "1 1 1", "99999999999999", "99999999999999")); },
                    "box.pcd", "header", "limit");
}

TEST(IoPcdErrors, WidthTimesHeightOverflowIsALimitError) {
  const std::string data = "FIELDS x y z\nWIDTH 18446744073709551615\nHEIGHT 3\nDATA ascii\n";
  expect_read_error([&] { read(data); }, "box.pcd", "header", "limit");
}

TEST(IoPcdErrors, DeclaredBinaryBytesAboveLimit) {
  ReadLimits limits;
  limits.max_bytes = 10000;
  const std::string data = header("x y z", "8 8 8", "F F F", "1 1 1", "1000", "1000", "binary");
  expect_read_error([&] { read(data, limits); }, "box.pcd", "header", "more than the limit of 10000 bytes");
}

TEST(IoPcdErrors, HugeCountIsALimitErrorNotAnOverflow) {
  const std::string data = header("x y z junk", "4 4 4 8", "F F F F", "1 1 1 4611686018427387904") + "1 2 3 4\n";
  expect_read_error([&] { read(data); }, "box.pcd", "line 5", "limit");
}

TEST(IoPcdErrors, InputLargerThanByteLimit) {
  ReadLimits limits;
  limits.max_bytes = 64;
  const std::string data = encode_pcd(test::sample_points(10), PcdEncoding::ascii);
  expect_read_error([&] { read(data, limits); }, "box.pcd", "byte 64", "more than the limit of 64 bytes");
}

TEST(IoPcdErrors, HeaderListsOfWrongLength) {
  expect_read_error([] { read(header("x y z", "4 4")); }, "box.pcd", "line 3", "SIZE has 2 values for 3 FIELDS");
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F F")); }, "box.pcd", "line 4", "TYPE has 4 values");
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F", "1 1")); }, "box.pcd", "line 5", "COUNT has 2 values");
}

TEST(IoPcdErrors, UnsupportedTypeAndSize) {
  expect_read_error([] { read(header("x y z", "4 2 4")); }, "box.pcd", "line 4", "unsupported TYPE 'F' with SIZE 2");
  expect_read_error([] { read(header("x y z", "4 4 4", "F Q F")); }, "box.pcd", "line 4", "unsupported TYPE 'Q'");
}

TEST(IoPcdErrors, CoordinateWithCountAboveOne) {
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F", "1 2 1")); }, "box.pcd", "line 5",
                    "field 'y' has COUNT 2");
}

TEST(IoPcdErrors, NonNumericHeaderValue) {
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F", "1 1 1", "two")); }, "box.pcd", "line 6",
                    "non-numeric value 'two' in WIDTH");
  expect_read_error([] { read(header("x y z", "4 4 4", "F F F", "1 1 1", "-2")); }, "box.pcd", "line 6",
                    "non-numeric");
}

TEST(IoPcdErrors, NotAPcdFile) {
  expect_read_error([] { read("ply\nformat ascii 1.0\n"); }, "box.pcd", "line 1", "unknown header keyword 'ply'");
  expect_read_error([] { read("# only a comment\n"); }, "box.pcd", "header", "no DATA line");
  expect_read_error([] { read("VERSION 0.7\nDATA ascii\n"); }, "box.pcd", "header", "no FIELDS line");
  expect_read_error([] { read("FIELDS x y z\nDATA ascii\n"); }, "box.pcd", "header", "no POINTS or WIDTH line");
}

TEST(IoPcdErrors, HostileBytesInMessagesStayOnOneLine) {
  const std::string data = header() + "1 2 3\n4 \x1b[31m\r\x01 6\n";
  expect_read_error([&] { read(data); }, "box.pcd", "line 11", "non-numeric");
}

}  // namespace
}  // namespace cloudshape::io
