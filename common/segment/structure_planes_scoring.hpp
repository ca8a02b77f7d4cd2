// Scoring of structure-plane hypotheses: the scored nodes column by column, so that the count of
// a plane's inliers is one loop the compiler vectorises, with the counts is_inlier's test gives.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/plane.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

// Nodes with their positions, normals and distance limits (band times their spacing) apart, in
// an order of their own (nearby nodes together: a count does not depend on the order), and per
// chunk of kChunk of them a box around their positions and their largest limit.
struct ScoredNodes {
  static constexpr std::size_t kChunk = 32;
  std::vector<double> x, y, z, nx, ny, nz, limit;
  std::vector<double> centre_x, centre_y, centre_z, half_x, half_y, half_z, chunk_limit;  // per full chunk

  ScoredNodes(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes, double band);
  std::size_t size() const { return x.size(); }
};

// How many of the nodes lie within their limit of plane `p` with normals within acos(min_cos)
// of its normal (either way): the same count, to the node, as testing each with
// |p.signed_distance(node)| <= limit && |normal . p.normal| >= min_cos on Eigen vectors.
// When that count cannot exceed `must_beat`, it may stop early and return a count no larger
// than `must_beat` (a hypothesis that cannot win is not counted out).
std::size_t count_plane_inliers(const ScoredNodes& nodes, const geometry::Plane& p, double min_cos,
                                std::size_t must_beat = 0);

}  // namespace cloudshape::segment
