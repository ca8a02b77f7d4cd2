#include "segment/remainder_graph.hpp"

#include <algorithm>
#include <cmath>

namespace cloudshape::segment {

std::optional<RemainderGraph> finer_remainder_graph(const PointList& points, const NeighbourGraph& graph,
                                                    const std::vector<char>& removed,
                                                    const config::SegmentConfig& cfg,
                                                    parallel::ThreadPool* pool) {
  if (!(cfg.remainder_refine > 1.0) || graph.size() == 0) return std::nullopt;
  std::size_t kept_nodes = 0;
  std::vector<double> spacing;
  for (std::uint32_t n = 0; n < graph.size(); ++n) {
    if (removed[n]) continue;
    ++kept_nodes;
    spacing.push_back(graph.spacing[n]);
  }
  if (kept_nodes == 0) return std::nullopt;
  std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
  const double coarse = spacing[spacing.size() / 2];
  // The voxel for the node budget alone; the sampling's floor can only make it coarser, so a
  // budget voxel already too coarse settles it before any pass over the points (an isolated
  // solid: nearly every node kept, the voxel the graph has).
  const double target = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const double for_budget = coarse * std::sqrt(static_cast<double>(kept_nodes) / target);
  if (for_budget * cfg.remainder_refine > coarse) return std::nullopt;

  RemainderGraph out;
  PointList rest;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const std::uint32_t n = graph.node_of_point[i];
    if (n == kNoNode || removed[n]) continue;
    out.points.push_back(i);
    rest.push_back(points[i]);
  }
  const double voxel = std::max(finest_voxel(rest, pool), for_budget);
  // The sampling only bounds how fine: any finer voxel than the scene graph's helps a small target.
  if (!(voxel > 0.0) || voxel >= coarse) return std::nullopt;
  out.graph = build_voxel_graph(rest, voxel, std::nullopt, cfg, pool);
  orient_to_viewpoint(out.graph, graph.viewpoint);
  return out;
}

}  // namespace cloudshape::segment
