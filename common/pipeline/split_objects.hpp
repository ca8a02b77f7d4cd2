// Separate objects of one cloud: connected components over a grid whose cell is a
// few resolutions, so objects apart by a clear gap become separate clouds.
#pragma once

#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::pipeline {

// Components of `points`, largest first, after a support plane (table, floor) is cut away
// (remove_support_plane). Cells of edge cfg.object_gap * resolution that
// touch (26-neighbourhood) join, so objects farther apart than 2*sqrt(3) cells are always
// split and points closer than one cell always joined. Components with fewer than
// cfg.min_object_fraction of the points are clutter and dropped (counted in *dropped), and so
// are narrow strips (spread across their length under cfg.fragment_max_width resolutions)
// smaller than cfg.fragment_max_share of the largest component: fragments a sensor leaves
// along silhouettes, not objects. A small solid is neither, so it stays.
// With splitting off, or nothing to split, the one component is the whole cloud.
// *support_removed, when given, says whether a support plane was cut away.
std::vector<PointList> split_objects(const PointList& points, double resolution,
                                     const config::PreprocessConfig& cfg,
                                     std::size_t* dropped = nullptr, bool* support_removed = nullptr);

// Connected components over cells of edge `cell` (26-neighbourhood), largest first.
std::vector<PointList> connected_components(const PointList& points, double cell);

// Spread (standard deviation) of non-empty `points` across their longest direction (the
// second principal axis): almost none for a strip along a silhouette edge.
double spread_across(const PointList& points);

}  // namespace cloudshape::pipeline
