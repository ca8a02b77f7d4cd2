// Exact single-view visibility for points sampled on a triangle mesh: a point is kept when the
// line of sight from the camera to it crosses no triangle of the mesh (ray casting on a BVH).
#pragma once

#include "geometry/point_cloud.hpp"
#include "synth/mesh_sampling.hpp"
#include "synth/triangle_bvh.hpp"

#include <Eigen/Core>
#include <vector>

namespace cloudshape::synth {

class MeshVisibility {
 public:
  // Builds the hierarchy once, so one mesh can be tested from many cameras or in many passes.
  // Throws std::invalid_argument on an out-of-range vertex index.
  MeshVisibility(const PointList& vertices, const std::vector<Triangle>& triangles);

  // The points (each on the mesh's surface) that a pinhole camera at `camera` sees: those whose
  // line of sight meets no triangle before it reaches them. Only the last millionth of the
  // mesh's size before the point is not tested, so the point's own triangle (and a neighbour
  // sharing the edge it lies on) cannot hide it; grazing faces are kept however steep, back
  // faces of a closed mesh are hidden by the front ones, and nothing leaks past a silhouette.
  // An open mesh shows its inside where the camera looks into it, as a real camera would.
  PointList visible(const PointList& points, const Eigen::Vector3d& camera) const;

 private:
  TriangleBvh bvh_;
  double self_margin_;
};

}  // namespace cloudshape::synth
