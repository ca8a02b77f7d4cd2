#include "segment/detail/concave_creases.hpp"

#include <algorithm>
#include <cmath>

#include "segment/detail/graph_moments.hpp"

namespace cloudshape::segment::detail {

std::vector<char> concave_creases(const NeighbourGraph& g, const CellLayout& cells,
                                  const config::SegmentConfig& cfg, parallel::ThreadPool* pool) {
  if (!(cfg.crease_degrees > 0.0)) return {};
  const double crease_cos = std::cos(cfg.crease_degrees * 3.14159265358979323846 / 180.0);
  const auto r = static_cast<std::ptrdiff_t>(std::max<std::int64_t>(1, cfg.normal_radius));
  // A border narrower than two radii: every flank node is off the cells, so no node is a centre.
  if (static_cast<std::size_t>(r) > cells.border / 2) return std::vector<char>(g.size(), 0);
  constexpr int kDirections[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  std::ptrdiff_t offsets[4];
  const auto padded_x = static_cast<std::ptrdiff_t>(cells.padded_x);
  for (int k = 0; k < 4; ++k) offsets[k] = kDirections[k][1] * padded_x + kDirections[k][0];
  const auto angle = [&](std::uint32_t a, std::uint32_t b) {
    return std::acos(std::clamp(g.normals[a].dot(g.normals[b]), -1.0, 1.0));
  };
  std::vector<char> centre(g.size(), 0);
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      const std::uint32_t* cell = cells.node_of_cell.data() + cells.cell_of_node[n];
      const double range = cells.range[n];
      // The node k cells along a direction (offset o), if there is one on this node's surface.
      const auto node_at = [&](std::ptrdiff_t k, std::ptrdiff_t o) {
        const std::uint32_t m = cell[k * o];
        return m != kNoNode && same_surface(range, cells.range[m], cfg.depth_jump) ? m : kNoNode;
      };
      for (const std::ptrdiff_t d : offsets) {
        const std::uint32_t p = node_at(-r, d), q = node_at(r, d);
        if (p == kNoNode || q == kNoNode) continue;
        if (!(g.normals[p].dot(g.normals[q]) < crease_cos &&
              (g.normals[p] - g.normals[q]).dot(g.nodes[p] - g.nodes[q]) < 0.0))
          continue;
        const std::uint32_t p2 = node_at(-2 * r, d), q2 = node_at(2 * r, d);
        if (p2 == kNoNode || q2 == kNoNode) continue;
        const double flank = cfg.crease_flank_share * angle(p, q);
        if (angle(p2, p) < flank && angle(q, q2) < flank) {
          centre[n] = 1;
          break;
        }
      }
    }
  });
  std::vector<char> crease = centre;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (centre[n]) g.for_neighbours(n, [&](std::uint32_t m) { crease[m] = 1; });
  }
  return crease;
}

}  // namespace cloudshape::segment::detail
