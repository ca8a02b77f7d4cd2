// Concave creases of an organized cloud's graph: nodes where two flat faces meet at a fold turned
// towards the sensor, which normals blurred over their windows and a curvature test do not show.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "parallel/thread_pool.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment::detail {

// The graph's pixel cells inside a border of `border` empty ones on every side: node_of_cell
// row-major over rows of padded_x (kNoNode: none), and per node its index there and its range
// (distance from the sensor). A border of two normal radii lets the creases look without bounds
// tests; one narrower than that is as wide as the cells reach, and no look that far finds a node.
struct CellLayout {
  std::size_t padded_x = 0, border = 0;
  std::vector<std::uint32_t> node_of_cell;
  std::vector<std::size_t> cell_of_node;
  std::vector<double> range;
};

// Per node, whether it lies on a concave crease (widened by one node: no patch grows across it
// diagonally). A node is on one when, along its row, its column or a diagonal, the nodes
// cfg.normal_radius cells either side (on its surface: ranges within cfg.depth_jump) have normals
// turned towards each other by more than cfg.crease_degrees, while each turns less than
// cfg.crease_flank_share of that to the node a further cfg.normal_radius out (flat flanks: the
// inside of a bowl turns evenly). Their normal windows do not overlap: one's noise is not in the
// other. Empty when cfg.crease_degrees is 0. The same for any `pool`.
std::vector<char> concave_creases(const NeighbourGraph& g, const CellLayout& cells,
                                  const config::SegmentConfig& cfg, parallel::ThreadPool* pool);

}  // namespace cloudshape::segment::detail
