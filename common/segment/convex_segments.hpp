// Objects apart by local convexity (after LCCP, Stein et al. 2014): the graph is cut into smooth
// patches, and adjacent patches are joined only where most of their junction is convex.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

// Orients every node's normal away from the centroid of its connected component (among the
// nodes not removed), for a graph without a viewpoint: right for convex solids, which is what a
// junction test between one solid's faces needs.
void orient_normals_outward(NeighbourGraph& graph, const std::vector<char>& removed);

// Per group of nodes (group[n] in 0..groups-1, or -1), whether it is narrow: its spread across
// its length (second principal axis) under max_width of its nodes' mean spacing.
std::vector<char> narrow_groups(const NeighbourGraph& graph, const std::vector<std::int32_t>& group,
                                std::int32_t groups, double max_width);

// Per node, its segment (0, 1, ...) or -1 for removed nodes. Patches grow over surface nodes
// (curvature under cfg.edge_curvature) across edges whose normals differ by less than
// cfg.smooth_degrees (a narrow component, a line, stays whole); edge nodes then join the nearest
// patch. Two adjacent patches join when at least cfg.convex_share of the edges between them are
// convex, judged between the surface nodes either side of the edge band
// ((n_a - n_b) . (x_a - x_b) >= 0, or normals within cfg.convex_tolerance_degrees). In a depth
// image (`depth_image`: an organized cloud's graph, whose nodes tile every face seen) a patch of a
// few offset flat pieces is first split into them (split_planar_pieces), and three more rules
// hold: patches meeting at an angle must share their crease (CreaseOverlap,
// cfg.crease_overlap and cfg.crease_band); a patch under cfg.min_object_nodes joins in a second
// pass, never bridging two groups whose own junction was rejected; and a segment two of whose
// patches meet concavely is cut along the flat one's plane (cut_at_concave_faces,
// cfg.concave_cut_band). A segment with fewer than cfg.min_object_nodes nodes is then absorbed by
// the neighbour it shares most edges with.
std::vector<std::int32_t> convex_segments(const NeighbourGraph& graph, const std::vector<char>& removed,
                                          const config::SegmentConfig& cfg, bool depth_image = false);

}  // namespace cloudshape::segment
