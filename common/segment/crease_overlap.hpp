// Whether two smooth patches that meet at an angle share their crease, as one solid's faces do:
// along the line where their planes cross, each patch's nodes near the other's plane span alike.
#pragma once

#include <cstdint>
#include <vector>

#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {

class CreaseOverlap {
 public:
  // `patch`: per node its patch (0..patches-1) or -1; `surface`: per node whether it is a
  // surface node (edge bands, whose normals blur two faces, are left out of every span).
  CreaseOverlap(const NeighbourGraph& graph, const std::vector<std::int32_t>& patch, const std::vector<char>& surface,
                std::int32_t patches, double band);

  // Along the crease (n_a x n_b, mean normals), the span of a's nodes within `band` node
  // spacings of b's plane and that of b's nodes near a's plane (their outer 2% left out) overlap
  // by at least min_share of the shorter. One solid's two faces share the edge between them;
  // faces of two solids that touch at a corner, or at a step finer than the graph (a box flush
  // beside a slightly taller or deeper one), reach that line side by side. True when there is
  // too little to judge (parallel or opposite patches, fewer than 3 nodes near the other plane).
  bool shares_crease(std::uint32_t a, std::uint32_t b, double parallel_cos, double min_share) const;

 private:
  struct Span {
    double lo = 0.0, hi = 0.0;
    bool valid = false;
  };
  Span span_near(std::uint32_t p, std::uint32_t other, const Eigen::Vector3d& line, double band) const;

  const NeighbourGraph& g_;
  double band_;
  std::vector<std::vector<std::uint32_t>> members_;
  std::vector<Eigen::Vector3d> normal_, centroid_;
  std::vector<double> spacing_;
};

}  // namespace cloudshape::segment
