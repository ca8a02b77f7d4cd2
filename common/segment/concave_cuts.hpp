// Segments cut along a flat face where another patch of the same segment meets it concavely
// (after CPC, Schoeler et al. 2015): a box stacked flush on a box, joined through their sides.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "config/stage_configs.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

// Two adjacent patches (a < b) and the length of their junction: the graph edges between them.
struct PatchJunction {
  std::uint32_t a, b, length;
};

// Junctions of adjacent patches, in the order of their ids: `concave`, mostly concave; `edges`,
// mostly a convex edge (normals turned apart beyond the convex tolerance).
struct JunctionPairs {
  std::vector<PatchJunction> concave, edges;
};

// `patch`: per node its smooth patch (0..patches-1) or -1; `surface`: per node whether it is a
// surface node (edge bands blur two faces and judge nothing); `group`: per patch its segment;
// `pairs`: the patches' junctions, and `rejudge` the junctions of any labelling (called after a
// cut splits a patch, so that its two pieces are judged apart).
//
// Local convexity joins two solids whenever any path of convex junctions links them: a box on a
// slightly larger box is one segment through their sides, although the lower box's top meets the
// upper box's front concavely. For such a pair inside one segment, the plane of either patch,
// when that patch is flat (cfg.min_object_nodes surface nodes or more, three standard deviations
// of them within cfg.concave_cut_band node spacings of their plane), cuts the segment in two:
// every patch goes to the side its surface nodes lie on beyond the band (the flat patch itself,
// and patches within the band, to its own side). A patch lying on both sides (more than
// cfg.concave_cut_cross_share of its surface nodes beyond the band either way) stops the cut when
// it is flat (a face of one solid runs through any plane inside it, so an L-shaped solid seen
// with its cap is never cut) or when either side's piece of it is not flat; otherwise it grew
// over two solids' parallel faces and is split: its nodes beyond the band become a patch of their
// own (`patch` and `patches` grow). A flat patch is split too when it spreads off its plane
// cfg.concave_cut_kink_ratio times as far as its two pieces off theirs: two solids' faces meeting
// at a kink (a box turned on a slightly larger one, the fronts grown into one patch where the
// lower top's strip runs out). No convex edge at least as long as the concave junction may run
// along the cut (two patches of cfg.min_object_nodes surface nodes or more, one either side,
// meeting at one: a solid's own faces, a can's lid and side, whose rim is longer than where a
// taller can beside it touches the lid); a shorter one is where the lower top's strip runs out
// under a box turned on a larger one, its front meeting the lower box's sides there. Each side
// must hold at least cfg.min_object_nodes nodes. Cuts
// repeat until none is left. Returns the new segment of every patch (new ids appended).
std::vector<std::uint32_t> cut_at_concave_faces(
    const NeighbourGraph& graph, std::vector<std::int32_t>& patch, const std::vector<char>& surface,
    std::int32_t& patches, std::vector<std::uint32_t> group, JunctionPairs pairs,
    const std::function<JunctionPairs(const std::vector<std::int32_t>& patch)>& rejudge, const config::SegmentConfig& cfg);

}  // namespace cloudshape::segment
