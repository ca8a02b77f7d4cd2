// Support-plane removal for real scenes: the table or floor the objects stand on is one big
// plane reaching well beyond them; it is cut away before the cloud is split into objects.
#pragma once

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::pipeline {

// Finds the dominant plane (RANSAC over the whole cloud, band cfg.support_band resolutions)
// and removes it when it is a support: it holds at least cfg.support_min_share of the points,
// at least 80% of the other points stand on one side of it, and it reaches beyond their
// footprint on three of four sides by cfg.support_margin of their extent (a solid's own face ends
// where its other faces do), and at most cfg.support_max_overlap of
// them lie over where the plane was seen (a solid's face lies under the rest of the solid;
// a table is hidden where the objects stand on it). Then only those points are returned (the plane and whatever lies
// below it are gone); otherwise the cloud as it is. *removed, when given, says which.
PointList remove_support_plane(const PointList& points, double resolution,
                               const config::PreprocessConfig& cfg, bool* removed = nullptr);

}  // namespace cloudshape::pipeline
