// Which beam of a multi-beam lidar frame (in its sensor's frame) each point lies on, and how many
// beams a set of points spans: an object seen on too few scan lines shows no vertical extent.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::segment {

// Per point, the beam it lies on, numbered by elevation from the origin: beams are the runs of
// adjacent occupied bins (cfg.scan_elevation_bin_degrees) holding a ring's worth of points, as
// scan_origin finds them; -1 for a point in no beam (a stray return, the origin itself).
std::vector<std::int32_t> scan_beam_of_points(const PointList& points, const config::SegmentConfig& cfg);

// The distinct beams (beam_of >= 0) of the points `indices` select.
std::size_t beams_spanned(const std::vector<std::int32_t>& beam_of, const std::vector<std::uint32_t>& indices);

}  // namespace cloudshape::segment
