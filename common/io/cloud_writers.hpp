// Writes point clouds as PCD (ascii, binary, binary_compressed), PLY (ascii, binary) or XYZ.
// Everything written reads back through the readers in this module.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::io {

enum class PcdEncoding { ascii, binary, binary_compressed };

// x y z as F4 floats, or F8 doubles with double_precision. Non-finite points are written as
// they are (the readers drop and count them). Throws std::runtime_error naming the path.
void write_pcd(const std::string& path, const PointList& points, PcdEncoding encoding,
               bool double_precision = false);

// binary selects binary_little_endian. Vertex properties are float, or double with double_precision.
void write_ply(const std::string& path, const PointList& points, bool binary, bool double_precision = false);

// One "x y z" line per point, each value with the shortest text that reads back exactly.
void write_xyz(const std::string& path, const PointList& points);

// A labelled cloud, organized when height > 1 (a depth frame): WIDTH x HEIGHT points in row-major
// order with empty pixels as NaN, fields x y z (F4) and label (U4, segmentation ground truth as in
// the Object Segmentation Database). Throws std::invalid_argument unless points and labels both
// hold width * height entries, std::runtime_error naming the path when the file cannot be written.
void write_labelled_pcd(const std::string& path, const PointList& points,
                        const std::vector<std::uint32_t>& labels, std::size_t width, std::size_t height,
                        PcdEncoding encoding);

// The exact bytes the writers put in a file, for in-memory transport and for tests.
std::string encode_pcd(const PointList& points, PcdEncoding encoding, bool double_precision = false);
std::string encode_ply(const PointList& points, bool binary, bool double_precision = false);
std::string encode_xyz(const PointList& points);
std::string encode_labelled_pcd(const PointList& points, const std::vector<std::uint32_t>& labels,
                                std::size_t width, std::size_t height, PcdEncoding encoding);

}  // namespace cloudshape::io
