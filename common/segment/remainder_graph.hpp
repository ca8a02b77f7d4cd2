// Each object at its own resolution: once structure is out of a voxel graph, what is left of a
// wide, sparse scene (a lidar's objects among its ground and walls) is re-gridded finer.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

struct RemainderGraph {
  NeighbourGraph graph;               // over `points` alone; node_of_point indexes into them
  std::vector<std::uint32_t> points;  // the remaining input points, indices into the input
};

// The points of the nodes not `removed`, as a voxel graph of their own whose voxel edge is
// chosen so that they fill about cfg.target_nodes nodes (`graph`'s median node spacing times the
// square root of kept nodes over the budget: a surface fills voxels with the inverse square of
// the edge), never finer than finest_voxel (their sampling). None when the budget's voxel is not
// at least cfg.remainder_refine times finer than that spacing (the graph already holds the
// remainder at its resolution: an isolated solid), or the sampling allows no finer voxel at all.
// A remainder the budget would grid much finer is gridded as finely as its sampling allows: a
// lidar frame's ball among its ring leftovers, whose sampling floor is 1.9 times finer than the
// scene graph, would otherwise be a few nodes. Keeps `graph`'s viewpoint (normals towards it).
std::optional<RemainderGraph> finer_remainder_graph(const PointList& points, const NeighbourGraph& graph,
                                                    const std::vector<char>& removed,
                                                    const config::SegmentConfig& cfg,
                                                    parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::segment
