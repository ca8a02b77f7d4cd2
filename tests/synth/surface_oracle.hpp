// Test oracle: an independent analytic description of each solid as a convex region.
// A point is on the closed surface exactly when the largest constraint value is zero.
#pragma once

#include "synth/ground_truth.hpp"
#include "synth/solid_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace cloudshape::synth::testing {

struct HalfSpace {
  Eigen::Vector3d normal;  // unit, outward
  double offset;           // n . q <= offset inside
};

// Local coordinates of a world point (inverse of Pose::to_world).
inline Eigen::Vector3d to_local(const Pose& pose, const Eigen::Vector3d& p) {
  return pose.axes * (p - pose.center);
}

inline std::vector<HalfSpace> polyhedron_faces(const SolidSpec& spec) {
  std::vector<HalfSpace> faces;
  const auto add_plane = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3d& c) {
    Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    if (n.dot(a) < 0) n = -n;  // all these solids contain the local origin
    faces.push_back({n, n.dot(a)});
  };
  if (spec.kind == ShapeKind::box) {
    const Eigen::Vector3d half(dimension(spec, "length") / 2, dimension(spec, "width") / 2,
                               dimension(spec, "height") / 2);
    for (int k = 0; k < 3; ++k) {
      faces.push_back({Eigen::Vector3d::Unit(k), half[k]});
      faces.push_back({-Eigen::Vector3d::Unit(k), half[k]});
    }
  } else if (spec.kind == ShapeKind::tetrahedron) {
    const auto v = tetrahedron_vertices(dimension(spec, "edge"));
    add_plane(v[1], v[2], v[3]);
    add_plane(v[0], v[1], v[2]);
    add_plane(v[0], v[2], v[3]);
    add_plane(v[0], v[3], v[1]);
  } else if (spec.kind == ShapeKind::pentagonal_prism) {
    const double h = dimension(spec, "height");
    const auto v = pentagon_vertices(dimension(spec, "side"));
    faces.push_back({Eigen::Vector3d::UnitX(), h / 2});
    faces.push_back({-Eigen::Vector3d::UnitX(), h / 2});
    for (int k = 0; k < 5; ++k) add_plane(v[k], v[(k + 1) % 5], v[k] + Eigen::Vector3d::UnitX());
  }
  return faces;
}

// Max over the solid's constraints, each a true (or lower-bound) distance: zero on the surface,
// negative inside, positive outside.
inline double surface_residual(const SolidSpec& spec, const Eigen::Vector3d& world) {
  const Eigen::Vector3d q = to_local(spec.pose, world);
  const double rho = std::hypot(q.y(), q.z());
  switch (spec.kind) {
    case ShapeKind::sphere:
      return q.norm() - dimension(spec, "radius");
    case ShapeKind::cylinder:
      return std::max(std::abs(q.x()) - dimension(spec, "height") / 2,
                      rho - dimension(spec, "radius"));
    case ShapeKind::cone: {
      const double r = dimension(spec, "radius"), h = dimension(spec, "height");
      const double lateral = (rho - r * (1.0 - q.x() / h)) / std::hypot(1.0, r / h);
      return std::max(-q.x(), lateral);
    }
    default: {
      double worst = -1e300;
      for (const auto& f : polyhedron_faces(spec))
        worst = std::max(worst, f.normal.dot(q) - f.offset);
      return worst;
    }
  }
}

}  // namespace cloudshape::synth::testing
