// The structure search's node sets, with few instructions per node: the nodes still searched,
// a plane's band and what lies above it, and the largest part of a set connected by edges.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/plane.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

// The nodes of `nodes` within band times their spacing of `p` with normals within acos(min_cos)
// of its normal (either way), in their order: the same nodes, to the bit, as
// |p.signed_distance(node)| <= band * spacing && |normal . p.normal| >= min_cos on each.
std::vector<std::uint32_t> band_nodes(const NeighbourGraph& g,
                                      const std::vector<std::uint32_t>& nodes,
                                      const geometry::Plane& p, double band, double min_cos);

// The nodes of `nodes` not flagged in `skip` whose height over `p`, p.signed_distance(node) /
// spacing, is not at most 0 (NaN too) and, when `lift` > 0, whose signed distance is not at most
// `lift` either, appended to `above`; those not flagged with a height in (low, high] to `near`;
// each in their order. (`lift` is the plane's own noise: its nodes lifted by it stand on nothing.)
void nodes_above(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes,
                 const std::vector<char>& skip, const geometry::Plane& p, double low, double high,
                 double lift, std::vector<std::uint32_t>& above, std::vector<std::uint32_t>& near);

// The nodes not `removed` appended to `active`, those of them not `tried` either to `searched`, and
// those of them with a curvature below `max_curvature` to `seeds`; each ascending.
void split_nodes(const NeighbourGraph& g, const std::vector<char>& removed,
                 const std::vector<char>& tried, double max_curvature,
                 std::vector<std::uint32_t>& active, std::vector<std::uint32_t>& searched,
                 std::vector<std::uint32_t>& seeds);

// The largest set of `members` (distinct) connected through graph edges among themselves, in the
// order a depth-first search from its first member visits them; the first such set on a tie.
std::vector<std::uint32_t> largest_connected(const NeighbourGraph& g,
                                             const std::vector<std::uint32_t>& members);

}  // namespace cloudshape::segment
