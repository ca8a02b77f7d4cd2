#include "segment/own_resolution.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/voxel_grid.hpp"

namespace cloudshape::segment {

bool finer_on_its_own(const PointList& own, double spacing, const config::SegmentConfig& cfg) {
  if (!(cfg.remainder_refine > 1.0) || own.size() < 3 || !(spacing > 0.0)) return false;
  const double target = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const double voxel = std::max(3.0 * geometry::mean_nearest_neighbour_distance(own),
                                geometry::bounding_box(own).diagonal() / std::sqrt(target));
  return voxel > 0.0 && voxel * cfg.remainder_refine <= spacing;
}

}  // namespace cloudshape::segment
