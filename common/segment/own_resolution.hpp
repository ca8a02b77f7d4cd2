// Each object at its own resolution: a segment of a voxel graph whose own points, gridded alone,
// would be much finer than the graph (a small target in a wide scene) is segmented again alone.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::segment {

// Whether the segment's points `own`, gridded alone for cfg.target_nodes voxels (never finer
// than three mean neighbour distances, build_voxel_graph's floor), gets a voxel at least
// cfg.remainder_refine times finer than `spacing`, the node spacing it has in the scene's graph.
bool finer_on_its_own(const PointList& own, double spacing, const config::SegmentConfig& cfg);

}  // namespace cloudshape::segment
