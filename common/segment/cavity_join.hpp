// Open containers kept whole: a segment seen from inside (a cup's inner wall over its rim) is
// concave towards the sensor, which no convex solid's surface is, so it joins its container.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

// How concave a group of nodes is: minus the mean of n . (x - c) over its nodes (c its
// centroid), over the RMS of |x - c|. About +0.8 for the inside of a half cylinder, 0 for a
// plane, negative for a convex surface (normals pointing away from its centre).
double concavity(const NeighbourGraph& graph, const std::vector<std::uint32_t>& nodes);

// Relabels segments (label[n] in 0..k-1, or -1): every segment of at least cfg.min_object_nodes
// nodes whose concavity reaches cfg.cavity_concavity joins the segment with the most nodes within
// cfg.cavity_gap of its mean node spacing from it (the container whose rim bounds it); labels stay dense.
void join_cavities(const NeighbourGraph& graph, std::vector<std::int32_t>& label, const config::SegmentConfig& cfg);

}  // namespace cloudshape::segment
