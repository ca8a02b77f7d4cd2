// The structure planes' per-node inlier test written plainly on Eigen vectors: the reference the
// vectorised scoring and node sets must match to the node (and in order).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/plane.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment::test {

// The nodes of `nodes`, in their order, within band times their spacing of `p` with normals within
// acos(min_cos) of its normal, either way.
inline std::vector<std::uint32_t> eigen_band(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes,
                                             const geometry::Plane& p, double band, double min_cos) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t n : nodes) {
    if (std::abs(p.signed_distance(g.nodes[n])) <= band * g.spacing[n] &&
        std::abs(g.normals[n].dot(p.normal)) >= min_cos) {
      out.push_back(n);
    }
  }
  return out;
}

}  // namespace cloudshape::segment::test
