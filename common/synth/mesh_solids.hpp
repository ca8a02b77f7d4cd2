// Solids beyond the six that the analytic sampler knows (frustum, prism, any tetrahedron) as posed
// triangle meshes, sampled with mesh_sampling and seen with mesh_visibility.
#pragma once

#include <array>

#include "geometry/polygon.hpp"
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

// A right prism whose cross-section, in the local y z plane about pose.center, is `polygon`
// (simple, counter-clockwise), extruded along pose.axes.row(0) from -height/2 to height/2;
// pose.center is then its centroid when the polygon's area centroid is the origin.
SolidMesh prism_mesh(const geometry::Polygon2& polygon, double height, const Pose& pose);

// The tetrahedron with these corners (any order, not coplanar).
SolidMesh tetrahedron_mesh(const std::array<Eigen::Vector3d, 4>& corners);

}  // namespace cloudshape::synth
