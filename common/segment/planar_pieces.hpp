// A smooth patch made of offset flat pieces: faces of different solids that touch at a corner
// with nearly parallel normals (a box stacked turned on another) grow into one patch; split them.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

// Splits each patch (patch[n] in 0..patches-1, -1 for nodes outside every patch) that is covered
// by two to cfg.piece_max_planes flat pieces: the largest connected group of its nodes within
// cfg.piece_band node spacings of one plane (normals within cfg.smooth_degrees of it), then the
// same on what is left, each of at least cfg.min_object_nodes nodes, together holding
// cfg.piece_cover of the patch. A flat face is one piece (not split); a curved one needs more
// pieces than that (not split). The first piece keeps the patch's label, each other gets a new one
// (patches grows); the nodes of a split patch in no piece get -1. Returns whether any patch split.
bool split_planar_pieces(const NeighbourGraph& graph, std::vector<std::int32_t>& patch,
                         std::int32_t& patches, const config::SegmentConfig& cfg);

}  // namespace cloudshape::segment
