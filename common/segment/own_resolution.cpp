#include "segment/own_resolution.hpp"

#include <algorithm>
#include <cmath>

#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

bool finer_on_its_own(const PointList& own, double spacing, const config::SegmentConfig& cfg,
                      parallel::ThreadPool* pool) {
  if (!(cfg.remainder_refine > 1.0) || own.size() < 3 || !(spacing > 0.0)) return false;
  const double voxel = budget_voxel(own, cfg, pool);
  return voxel > 0.0 && voxel * cfg.remainder_refine <= spacing;
}

}  // namespace cloudshape::segment
