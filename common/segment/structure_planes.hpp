// Structure of a scene: the tables, floors and walls that objects stand on or against, told
// from a solid's own large face by what stands on the plane's open side and how far it reaches.
#pragma once

#include <cstddef>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/plane.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

struct StructurePlane {
  geometry::Plane plane;        // normal towards the side things stand on
  std::size_t nodes = 0;        // nodes removed with it
};

// Finds, one after the other, the plane through most nodes whose normals agree with it
// (cfg.structure_band node spacings, cfg.structure_normal_degrees), and removes its largest
// connected part (sets `removed`) while it holds cfg.structure_min_share of the nodes, at least
// cfg.structure_min_standing nodes stand on its open side (the viewer's, else the side most other
// nodes are on) and meet it inside (plane cfg.structure_margin_cells beyond where their surface,
// followed down its own slope, meets the plane, in all four in-plane directions; every node in the
// plane's band counts there, the table beyond an object's shadow too), and its area is
// at least cfg.structure_reach times their footprint, and, for every plane after the first found,
// the surface joined to it reaches behind it no more than cfg.structure_max_behind of its narrower
// extent: a solid's own face has its solid behind it, covers no more than the solid does, and
// meets the solid's other faces at its own edges (a cone's side leans over its base, but meets it
// at the base's edge; a box beside a box that stands out of it stands inside the plane of both
// fronts, but the box's top goes back from its front as deep as the box; the first support is the
// scene's, a kitchen counter's top over its deep front too). Deterministic for cfg.seed,
// whatever `pool` scores the hypotheses.
// `from_inside`: the graph's viewpoint is a lidar's among its ground and walls; a plane with at
// least cfg.structure_enclosing of the other nodes on the sensor's side and spanning
// cfg.structure_span of the scene (standard deviations along the longest axes) is then structure
// too, and all its nodes in the band go with it (a wall's parts between windows too); a part apart
// from the plane's connected one only within the noise the connected one shows (a ball on the
// ground rises above it).
// `reaches`, if given, is set when a plane tried reaches cfg.structure_reach times beyond what
// stands on it, structure or not, and the search stops there: the caller asks only whether the
// graph holds a candidate support at all (the planes returned are then not all there are).
std::vector<StructurePlane> remove_structure(const NeighbourGraph& graph, const config::SegmentConfig& cfg,
                                             std::vector<char>& removed, parallel::ThreadPool* pool = nullptr,
                                             bool from_inside = false, bool* reaches = nullptr);

}  // namespace cloudshape::segment
