#include "synth/solid_visibility.hpp"

#include <cmath>
#include <limits>

#include "synth/surface_normal.hpp"

namespace cloudshape::synth {

PointList visible_on_solids(const PointList& points, const std::vector<SolidSpec>& solids,
                            const Eigen::Vector3d& camera) {
  // A line of sight that only grazes another solid within a millionth of its size is clear.
  std::vector<double> margin;
  for (const auto& spec : solids) margin.push_back(1e-6 * characteristic_size(spec));
  PointList kept;
  kept.reserve(points.size());
  for (const auto& p : points) {
    std::size_t owner = 0;
    SurfaceContact on;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < solids.size(); ++k) {
      const SurfaceContact c = surface_contact(solids[k], p);
      if (std::abs(c.residual) < best) best = std::abs(c.residual), on = c, owner = k;
    }
    if (!(on.normal.dot(camera - p) > 0.0)) continue;
    bool hidden = false;
    for (std::size_t k = 0; k < solids.size() && !hidden; ++k)
      hidden = k != owner && segment_enters(solids[k], p, camera, margin[k]);
    if (!hidden) kept.push_back(p);
  }
  return kept;
}

}  // namespace cloudshape::synth
