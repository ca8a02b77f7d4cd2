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
  const auto cells_x = static_cast<std::ptrdiff_t>(cells.cells_x),
             cells_y = static_cast<std::ptrdiff_t>(cells.cells_y);
  constexpr int kDirections[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  const auto angle = [&](std::uint32_t a, std::uint32_t b) {
    return std::acos(std::clamp(g.normals[a].dot(g.normals[b]), -1.0, 1.0));
  };
  std::vector<char> centre(g.size(), 0);
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      const auto cx = static_cast<std::ptrdiff_t>(cells.cell_of_node[n][0]);
      const auto cy = static_cast<std::ptrdiff_t>(cells.cell_of_node[n][1]);
      const double range = cells.range[n];
      // The node k cells along d, if there is one on this node's surface.
      const auto node_at = [&](std::ptrdiff_t k, const int* d) {
        const std::ptrdiff_t x = cx + k * d[0], y = cy + k * d[1];
        if (x < 0 || y < 0 || x >= cells_x || y >= cells_y) return kNoNode;
        const std::uint32_t m = cells.node_of_cell[static_cast<std::size_t>(y * cells_x + x)];
        return m != kNoNode && same_surface(range, cells.range[m], cfg.depth_jump) ? m : kNoNode;
      };
      for (const auto& d : kDirections) {
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
