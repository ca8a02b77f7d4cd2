#include "segment/remainder_graph.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/voxel_grid.hpp"

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

  RemainderGraph out;
  PointList rest;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const std::uint32_t n = graph.node_of_point[i];
    if (n == kNoNode || removed[n]) continue;
    out.points.push_back(i);
    rest.push_back(points[i]);
  }
  const double target = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const double finest = 3.0 * geometry::mean_nearest_neighbour_distance(rest);
  const double voxel = std::max(finest, coarse * std::sqrt(static_cast<double>(kept_nodes) / target));
  if (!(voxel > 0.0) || voxel * cfg.remainder_refine > coarse) return std::nullopt;
  // build_voxel_graph takes its voxel from the diagonal and the node budget: the budget that gives
  // this voxel (it is never finer than its own floor either).
  const geometry::Bounds box = geometry::bounding_box(rest);
  config::SegmentConfig fine = cfg;
  const double budget = std::pow(box.diagonal() / voxel, 2.0);
  if (!(budget < 1e15)) return std::nullopt;
  fine.target_nodes = static_cast<std::int64_t>(budget) + 1;
  out.graph = build_voxel_graph(rest, fine, pool);
  orient_to_viewpoint(out.graph, graph.viewpoint);
  return out;
}

}  // namespace cloudshape::segment
