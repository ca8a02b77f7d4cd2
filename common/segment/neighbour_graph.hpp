// A cloud as a graph for segmentation: nodes (one per pixel cell of an organized cloud, one per
// voxel otherwise) with surface normals, edges between neighbours that are not across a depth jump.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::geometry {
struct Bounds;
}  // namespace cloudshape::geometry

namespace cloudshape::segment {

inline constexpr std::uint32_t kNoNode = std::numeric_limits<std::uint32_t>::max();

struct NeighbourGraph {
  PointList nodes;
  std::vector<Eigen::Vector3d> normals;  // unit; towards the viewpoint when there is one
  std::vector<double> curvature;         // surface variation of each node's neighbourhood
  std::vector<double> spacing;           // each node's typical distance to its neighbours
  std::vector<char> crease;              // organized graphs: per node, on a concave crease; empty otherwise
  std::vector<std::uint32_t> adjacency_begin;  // CSR: neighbours of n are adjacency[begin[n] .. begin[n+1])
  std::vector<std::uint32_t> adjacency;
  std::vector<std::uint32_t> node_of_point;    // per input point: its node, or kNoNode
  std::optional<Point> viewpoint;              // the sensor's position, when known (organized clouds)
  // Organized graphs: each pixel's depth carries noise of its own, enough to tilt a normal from
  // neighbouring pixels beyond half of smooth_degrees (the normal windows spread for it).
  bool noisy_pixels = false;

  std::size_t size() const { return nodes.size(); }
  template <class F>
  void for_neighbours(std::uint32_t n, F&& f) const {
    for (std::uint32_t e = adjacency_begin[n]; e < adjacency_begin[n + 1]; ++e) f(adjacency[e]);
  }
};

// Organized clouds: two pixels or cells lie on one surface when their ranges (distances from the
// sensor) differ by at most depth_jump of the nearer one.
inline bool same_surface(double range_a, double range_b, double depth_jump) {
  return std::abs(range_a - range_b) <= depth_jump * std::min(range_a, range_b);
}

// Organized cloud (grid.organized()): cells of s x s pixels, s chosen so that about
// cfg.target_nodes cells hold points; a cell's node is one of its pixels; 8-neighbour cells are
// connected unless their ranges (distance from the sensor at the origin) differ by more than
// cfg.depth_jump of the nearer range. Normals from the pixels in a window of cfg.normal_radius
// cells on the same side of every depth jump.
NeighbourGraph build_organized_graph(const PointList& points, const GridLayout& grid,
                                     const config::SegmentConfig& cfg, parallel::ThreadPool* pool = nullptr);

// The finest voxel edge a graph of `points` may have: three mean nearest-neighbour distances (a
// sample of 4 000; the same for any `pool`), and no finer than a cell key's 21 bits per axis allow.
double finest_voxel(const PointList& points, parallel::ThreadPool* pool = nullptr);

// The voxel edge build_voxel_graph starts from: the bounding box's diagonal over the square root
// of cfg.target_nodes, never finer than finest_voxel, grown by the square root of the occupied
// voxels' excess over cfg.voxel_target_nodes (a surface fills voxels with the inverse square of
// the edge).
double budget_voxel(const PointList& points, const config::SegmentConfig& cfg, parallel::ThreadPool* pool = nullptr);

// budget_voxel, and the same for `fewer` voxel target nodes instead of cfg.voxel_target_nodes
// (never finer), from one pass over the points: {budget_voxel, coarser}. `bounds`, if given, must
// be bounding_box(points) (a caller that has it saves the pass).
std::pair<double, double> budget_voxels(const PointList& points, const config::SegmentConfig& cfg,
                                        std::int64_t fewer, parallel::ThreadPool* pool = nullptr,
                                        const geometry::Bounds* bounds = nullptr);

// Any cloud: voxels of budget_voxel's edge, grown by a quarter at a time while more than 1.3
// cfg.target_nodes are occupied; a voxel's node is its centroid, 26-neighbour voxels are
// connected; normals from the cfg.normal_neighbours nearest nodes, unoriented (no viewpoint).
// A `pool` runs the neighbour search and the normals in blocks of nodes: the same graph.
NeighbourGraph build_voxel_graph(const PointList& points, const config::SegmentConfig& cfg,
                                 parallel::ThreadPool* pool = nullptr);

// The same with the voxel edge given (never below 1e-300), grown only while more than 1.3
// `max_nodes` are occupied (none: not grown). `bounds` as for budget_voxels.
NeighbourGraph build_voxel_graph(const PointList& points, double voxel,
                                 std::optional<std::int64_t> max_nodes,
                                 const config::SegmentConfig& cfg,
                                 parallel::ThreadPool* pool = nullptr,
                                 const geometry::Bounds* bounds = nullptr);

// Sets the graph's viewpoint and, when there is one, turns every normal towards it (a lidar
// frame seen from its sensor).
void orient_to_viewpoint(NeighbourGraph& graph, const std::optional<Point>& viewpoint);

}  // namespace cloudshape::segment
