// Each object at its own resolution: a segment of a voxel graph whose own points, gridded alone,
// would be much finer than the graph (a small target in a wide scene) is segmented again alone.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::segment {

// Whether the segment's points `own`, gridded alone (budget_voxel: build_voxel_graph's voxel
// before any growth), get a voxel at least cfg.remainder_refine times finer than `spacing`, the
// node spacing they have in the scene's graph. A `pool` runs the sampling estimate: the same answer.
bool finer_on_its_own(const PointList& own, double spacing, const config::SegmentConfig& cfg,
                      parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::segment
