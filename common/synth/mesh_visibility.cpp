#include "synth/mesh_visibility.hpp"

namespace cloudshape::synth {

MeshVisibility::MeshVisibility(const PointList& vertices, const std::vector<Triangle>& triangles)
    : bvh_(vertices, triangles),
      self_margin_(bvh_.bounds().isEmpty() ? 0.0 : 1e-6 * bvh_.bounds().diagonal().norm()) {}

PointList MeshVisibility::visible(const PointList& points, const Eigen::Vector3d& camera) const {
  PointList kept;
  kept.reserve(points.size());
  for (const auto& p : points) {
    const Eigen::Vector3d sight = p - camera;
    const double distance = sight.norm();
    if (!(distance > self_margin_)) continue;  // at the camera itself: nothing to see
    if (!bvh_.segment_hits(camera, sight, 1.0 - self_margin_ / distance)) kept.push_back(p);
  }
  return kept;
}

}  // namespace cloudshape::synth
