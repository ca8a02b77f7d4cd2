// Test meshes with known geometry: axis-aligned boxes as closed triangle meshes, each face cut
// into a grid of triangles (so lines of sight meet many shared edges), and an exact oracle.
#pragma once

#include "synth/mesh_sampling.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

namespace cloudshape::synth::test {

struct TriangleMesh {
  PointList vertices;
  std::vector<Triangle> triangles;
};

// Appends the closed surface of `box` to `mesh`, each face split into cuts x cuts quads of two
// triangles.
inline void add_box(TriangleMesh& mesh, const Eigen::AlignedBox3d& box, int cuts) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      for (int i = 0; i <= cuts; ++i)
        for (int j = 0; j <= cuts; ++j) {
          Eigen::Vector3d p;
          p[axis] = side ? box.max()[axis] : box.min()[axis];
          p[u] = box.min()[u] + box.sizes()[u] * i / cuts;
          p[v] = box.min()[v] + box.sizes()[v] * j / cuts;
          mesh.vertices.push_back(p);
        }
      const auto at = [&](int i, int j) { return first + std::uint32_t(i * (cuts + 1) + j); };
      for (int i = 0; i < cuts; ++i)
        for (int j = 0; j < cuts; ++j) {
          mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
}

// Whether the line of sight from `camera` to `p` (a point on the surface of the union of
// `boxes`) passes through the open interior of any box: the exact truth for "p is hidden".
// Interior overlaps of length under `slack` (relative to the segment) are ignored, so a point
// exactly on an edge or a sight line grazing a face does not count as hidden.
inline bool sight_line_blocked(const std::vector<Eigen::AlignedBox3d>& boxes,
                               const Eigen::Vector3d& camera, const Eigen::Vector3d& p,
                               double slack = 1e-9) {
  const Eigen::Vector3d d = p - camera;
  for (const auto& box : boxes) {
    double near = 0.0, far = 1.0;
    for (int a = 0; a < 3; ++a) {
      if (d[a] == 0.0) {
        if (camera[a] <= box.min()[a] || camera[a] >= box.max()[a]) near = 1.0, far = 0.0;
        continue;
      }
      double t0 = (box.min()[a] - camera[a]) / d[a], t1 = (box.max()[a] - camera[a]) / d[a];
      if (t0 > t1) std::swap(t0, t1);
      near = std::max(near, t0);
      far = std::min(far, t1);
    }
    if (far - near > slack) return true;
  }
  return false;
}

}  // namespace cloudshape::synth::test
