// Solids beyond the six that the analytic sampler knows (frustum, any tetrahedron) as posed
// triangle meshes, sampled with mesh_sampling and seen with mesh_visibility.
#pragma once

#include <array>

#include "synth/ground_truth.hpp"
#include "synth/mesh_sampling.hpp"

namespace cloudshape::synth {

struct SolidMesh {
  PointList vertices;
  std::vector<Triangle> triangles;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // the solid's centroid
  double size = 0.0;                                 // its largest extent
};

// A frustum with its larger end (radius) centred at pose.center, pose.axes.row(0) from that
// end towards the smaller one (top_radius) `height` away; `segments` facets around (the chord
// error is radius * (1 - cos(pi / segments))).
SolidMesh frustum_mesh(double radius, double top_radius, double height, const Pose& pose, int segments = 512);

// The tetrahedron with these corners (any order, not coplanar).
SolidMesh tetrahedron_mesh(const std::array<Eigen::Vector3d, 4>& corners);

}  // namespace cloudshape::synth
