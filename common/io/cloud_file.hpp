// What every point-cloud reader returns, and the limits that protect it from absurd input.
// Plain data only: the readers live in pcd_reader.hpp, ply_reader.hpp, xyz_reader.hpp, cloud_reader.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::io {

// Checked before anything is allocated from a header value, so a lying or hostile
// file costs at most these amounts.
struct ReadLimits {
  std::size_t max_points = 50'000'000;
  std::size_t max_bytes = 2'000'000'000ULL;
};

struct CloudFile {
  PointList points;                    // finite points only, in file order
  std::size_t non_finite_dropped = 0;  // points with NaN/Inf in x, y or z
  // A PCD with HEIGHT > 1 keeps its pixel layout (grid.pixel[i] is where points[i] sat);
  // empty for every other file.
  GridLayout grid;
  // Per point, the value of an integer field named "label" (segmentation ground truth, as
  // in the Object Segmentation Database) when the PCD has one; empty otherwise.
  std::vector<std::uint32_t> labels;
  // "pcd-ascii", "pcd-binary", "pcd-binary_compressed", "ply-ascii",
  // "ply-binary_little_endian" or "xyz".
  std::string format;
};

}  // namespace cloudshape::io
