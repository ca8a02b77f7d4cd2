// Writes point clouds as PCD (ascii, binary, binary_compressed), PLY (ascii, binary) or XYZ.
// Everything written reads back through the readers in this module.
#include "io/cloud_writers.hpp"

#include <lzf.h>

#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace cloudshape::io {
namespace {

// Shortest representation that parses back to the same float/double: exact round trips
// without printing 17 digits for every value.
template <typename T>
void append_number(std::string& out, T value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

template <typename T>
void append_text_rows(std::string& out, const PointList& points) {
  out.reserve(out.size() + points.size() * 3 * 16);
  for (const Point& p : points) {
    append_number(out, static_cast<T>(p.x()));
    out += ' ';
    append_number(out, static_cast<T>(p.y()));
    out += ' ';
    append_number(out, static_cast<T>(p.z()));
    out += '\n';
  }
}

template <typename T>
void append_binary_rows(std::string& out, const PointList& points) {
  const std::size_t start = out.size();
  out.resize(start + points.size() * 3 * sizeof(T));
  char* cursor = out.data() + start;
  for (const Point& p : points) {
    for (int a = 0; a < 3; ++a) {
      const T value = static_cast<T>(p[a]);
      std::memcpy(cursor, &value, sizeof(T));
      cursor += sizeof(T);
    }
  }
}

// The binary_compressed body: the compressed and raw sizes, then the LZF stream of `raw`.
void append_lzf_block(std::string& out, const void* raw, std::size_t raw_size) {
  // LZF grows incompressible input by at most one byte in 32, plus a little.
  std::vector<char> packed(raw_size + raw_size / 16 + 64);
  const auto in_size = static_cast<unsigned int>(raw_size);
  const unsigned int packed_size =
      raw_size == 0 ? 0 : lzf_compress(raw, in_size, packed.data(), static_cast<unsigned int>(packed.size()));
  if (raw_size != 0 && packed_size == 0) throw std::runtime_error("LZF compression failed");
  const std::uint32_t sizes[2] = {packed_size, in_size};
  out.append(reinterpret_cast<const char*>(sizes), sizeof sizes);
  out.append(packed.data(), packed_size);
}

template <typename T>
void append_compressed_block(std::string& out, const PointList& points) {
  const std::size_t n = points.size();
  const std::size_t raw_size = n * 3 * sizeof(T);
  if (raw_size > UINT_MAX / 2) throw std::runtime_error("too many points for a binary_compressed PCD");
  // PCD stores compressed clouds field by field: all x, then all y, then all z.
  std::vector<T> soa(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) soa[a * n + i] = static_cast<T>(points[i][a]);
  }
  append_lzf_block(out, soa.data(), raw_size);
}

// One row of x y z label per point, as float coordinates and an unsigned label.
void append_labelled_text(std::string& out, const PointList& points, const std::vector<std::uint32_t>& labels) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      append_number(out, static_cast<float>(points[i][a]));
      out += ' ';
    }
    append_number(out, labels[i]);
    out += '\n';
  }
}

void append_labelled_binary(std::string& out, const PointList& points, const std::vector<std::uint32_t>& labels) {
  const std::size_t start = out.size();
  out.resize(start + points.size() * 16);
  char* cursor = out.data() + start;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int a = 0; a < 3; ++a) {
      const auto value = static_cast<float>(points[i][a]);
      std::memcpy(cursor, &value, 4);
      cursor += 4;
    }
    std::memcpy(cursor, &labels[i], 4);
    cursor += 4;
  }
}

void append_labelled_compressed(std::string& out, const PointList& points,
                                const std::vector<std::uint32_t>& labels) {
  const std::size_t n = points.size();
  const std::size_t raw_size = n * 16;
  if (raw_size > UINT_MAX / 2) throw std::runtime_error("too many points for a binary_compressed PCD");
  // Field by field, as PCD stores compressed clouds: all x, all y, all z, then all labels.
  std::vector<char> soa(raw_size);
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      const auto value = static_cast<float>(points[i][a]);
      std::memcpy(soa.data() + (a * n + i) * 4, &value, 4);
    }
    std::memcpy(soa.data() + (3 * n + i) * 4, &labels[i], 4);
  }
  append_lzf_block(out, soa.data(), raw_size);
}

void write_file(const std::string& path, const std::string& bytes) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(errno));
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  const int write_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    throw std::runtime_error(path + ": write failed: " + std::strerror(written ? errno : write_errno));
  }
}

}  // namespace

std::string encode_pcd(const PointList& points, PcdEncoding encoding, bool double_precision) {
  const std::string n = std::to_string(points.size());
  const char* kind = encoding == PcdEncoding::ascii    ? "ascii"
                     : encoding == PcdEncoding::binary ? "binary"
                                                       : "binary_compressed";
  std::string out = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\n";
  out += double_precision ? "SIZE 8 8 8\n" : "SIZE 4 4 4\n";
  out += "TYPE F F F\nCOUNT 1 1 1\nWIDTH " + n + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + n +
         "\nDATA " + kind + "\n";
  switch (encoding) {
    case PcdEncoding::ascii:
      double_precision ? append_text_rows<double>(out, points) : append_text_rows<float>(out, points);
      break;
    case PcdEncoding::binary:
      double_precision ? append_binary_rows<double>(out, points) : append_binary_rows<float>(out, points);
      break;
    case PcdEncoding::binary_compressed:
      double_precision ? append_compressed_block<double>(out, points)
                       : append_compressed_block<float>(out, points);
      break;
  }
  return out;
}

std::string encode_ply(const PointList& points, bool binary, bool double_precision) {
  const char* type = double_precision ? "double" : "float";
  std::string out = "ply\nformat ";
  out += binary ? "binary_little_endian" : "ascii";
  out += " 1.0\ncomment written by cloudshape\nelement vertex " + std::to_string(points.size()) + "\n";
  for (const char* axis : {"x", "y", "z"}) out += std::string("property ") + type + " " + axis + "\n";
  out += "end_header\n";
  if (binary) {
    double_precision ? append_binary_rows<double>(out, points) : append_binary_rows<float>(out, points);
  } else {
    double_precision ? append_text_rows<double>(out, points) : append_text_rows<float>(out, points);
  }
  return out;
}

std::string encode_xyz(const PointList& points) {
  // An empty file is a read error (it is usually a failed export), so an empty cloud
  // is written as a comment line to keep the round trip intact.
  std::string out = points.empty() ? "# empty cloud\n" : "";
  append_text_rows<double>(out, points);
  return out;
}

std::string encode_labelled_pcd(const PointList& points, const std::vector<std::uint32_t>& labels,
                                std::size_t width, std::size_t height, PcdEncoding encoding) {
  if (points.size() != width * height || labels.size() != points.size())
    throw std::invalid_argument("labelled PCD: " + std::to_string(points.size()) + " points and " +
                                std::to_string(labels.size()) + " labels for a " + std::to_string(width) +
                                " x " + std::to_string(height) + " grid");
  const char* kind = encoding == PcdEncoding::ascii    ? "ascii"
                     : encoding == PcdEncoding::binary ? "binary"
                                                       : "binary_compressed";
  std::string out =
      "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z label\nSIZE 4 4 4 4\n"
      "TYPE F F F U\nCOUNT 1 1 1 1\nWIDTH " +
      std::to_string(width) + "\nHEIGHT " + std::to_string(height) + "\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
      std::to_string(points.size()) + "\nDATA " + kind + "\n";
  switch (encoding) {
    case PcdEncoding::ascii:
      append_labelled_text(out, points, labels);
      break;
    case PcdEncoding::binary:
      append_labelled_binary(out, points, labels);
      break;
    case PcdEncoding::binary_compressed:
      append_labelled_compressed(out, points, labels);
      break;
  }
  return out;
}

void write_labelled_pcd(const std::string& path, const PointList& points,
                        const std::vector<std::uint32_t>& labels, std::size_t width, std::size_t height,
                        PcdEncoding encoding) {
  std::string bytes;
  try {
    bytes = encode_labelled_pcd(points, labels, width, height, encoding);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  write_file(path, bytes);
}

void write_pcd(const std::string& path, const PointList& points, PcdEncoding encoding, bool double_precision) {
  std::string bytes;
  try {
    bytes = encode_pcd(points, encoding, double_precision);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  write_file(path, bytes);
}

void write_ply(const std::string& path, const PointList& points, bool binary, bool double_precision) {
  write_file(path, encode_ply(points, binary, double_precision));
}

void write_xyz(const std::string& path, const PointList& points) { write_file(path, encode_xyz(points)); }

}  // namespace cloudshape::io
