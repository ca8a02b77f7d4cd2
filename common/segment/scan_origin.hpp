// Whether an unorganized cloud is a multi-beam lidar frame in its sensor's own frame: its points
// then lie on a few elevation angles seen from the origin, which is the sensor (the viewpoint).
#pragma once

#include <optional>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::segment {

// The origin, when the points' elevations from it (in bins of cfg.scan_elevation_bin_degrees)
// fall, cfg.scan_beam_share of them, into at least four beams: runs of full bins, on average
// no wider than cfg.scan_beam_bins, with empty bins between them and about ten points a beam at
// least. A surface sampled any other way fills long runs of bins. None otherwise. A `pool` bins
// blocks of points on its threads (counts summed: the same answer).
std::optional<Point> scan_origin(const PointList& points, const config::SegmentConfig& cfg,
                                 parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::segment
