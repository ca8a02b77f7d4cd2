// A bounding-volume hierarchy over a triangle mesh that answers one question exactly and fast:
// does a line segment cross any triangle? The occlusion test behind exact mesh visibility.
#pragma once

#include "geometry/point_cloud.hpp"
#include "synth/mesh_sampling.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace cloudshape::synth {

class TriangleBvh {
 public:
  // Zero-area and non-finite triangles are left out (they hide nothing). Throws
  // std::invalid_argument on an out-of-range vertex index.
  TriangleBvh(const PointList& vertices, const std::vector<Triangle>& triangles);

  // True when origin + t * direction meets a triangle for some t in (0, t_max). A segment
  // through a shared edge or vertex counts as meeting it (edges are closed), so a line of
  // sight cannot slip between two triangles of a closed surface.
  bool segment_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                    double t_max) const;

  // The box around every kept triangle (empty when there is none).
  const Eigen::AlignedBox3d& bounds() const { return nodes_.empty() ? empty_ : nodes_[0].box; }

 private:
  struct Corners {
    Eigen::Vector3d a, ab, ac;  // a vertex and the two edges leaving it
  };
  struct Node {
    Eigen::AlignedBox3d box;
    std::uint32_t first = 0;  // leaf: first triangle; inner: index of the second child
    std::uint32_t count = 0;  // triangles in a leaf, 0 for an inner node
  };

  std::uint32_t build(std::uint32_t first, std::uint32_t count,
                      std::vector<Eigen::Vector3d>& centroids);

  std::vector<Corners> triangles_;
  std::vector<Node> nodes_;
  Eigen::AlignedBox3d empty_;
};

}  // namespace cloudshape::synth
