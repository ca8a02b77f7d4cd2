// Which beam of a multi-beam lidar frame (in its sensor's frame) each point lies on, and how many
// beams a set of points spans: an object seen on too few scan lines shows no vertical extent.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::segment {

// A beam holds a ring's worth of returns; fewer in a run of bins are strays (a sparse cloud leaves
// bins occupied by chance alone).
inline constexpr std::size_t kMinPointsPerBeam = 10;

// The elevation bin (of `bin_degrees`) of `p` seen from the origin; none for the origin itself or
// a non-finite point.
std::optional<std::int64_t> elevation_bin(const Point& p, double bin_degrees);

// A beam: a run of adjacent occupied elevation bins, empty ones either side, holding at least
// kMinPointsPerBeam points.
struct ElevationBeam {
  std::int64_t first_bin = 0, last_bin = 0;
  std::size_t points = 0;
};

// The beams of per-bin point counts sorted by bin, lowest first.
std::vector<ElevationBeam> elevation_beams(const std::vector<std::pair<std::int64_t, std::size_t>>& sorted_counts);

// Per point, the beam it lies on, numbered by elevation from the origin: beams are the runs of
// adjacent occupied bins (cfg.scan_elevation_bin_degrees) holding a ring's worth of points, as
// scan_origin finds them; -1 for a point in no beam (a stray return, the origin itself).
std::vector<std::int32_t> scan_beam_of_points(const PointList& points, const config::SegmentConfig& cfg);

// The distinct beams (beam_of >= 0) of the points `indices` select.
std::size_t beams_spanned(const std::vector<std::int32_t>& beam_of, const std::vector<std::uint32_t>& indices);

}  // namespace cloudshape::segment
