// Support function and bounding radius of the six solids, from their vertices or, for the round
// ones, in closed form (a circle of radius r normal to a reaches r * |d x a| along d).
#include "synth/solid_support.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "synth/solid_geometry.hpp"

namespace cloudshape::synth {

namespace {

std::vector<Eigen::Vector3d> local_vertices(const SolidSpec& spec) {
  std::vector<Eigen::Vector3d> v;
  switch (spec.kind) {
    case ShapeKind::box: {
      const Eigen::Vector3d half(dimension(spec, "length") / 2, dimension(spec, "width") / 2,
                                 dimension(spec, "height") / 2);
      for (int k = 0; k < 8; ++k)
        v.emplace_back((k & 1 ? 1 : -1) * half.x(), (k & 2 ? 1 : -1) * half.y(),
                       (k & 4 ? 1 : -1) * half.z());
      break;
    }
    case ShapeKind::tetrahedron:
      for (const auto& p : tetrahedron_vertices(dimension(spec, "edge"))) v.push_back(p);
      break;
    case ShapeKind::pentagonal_prism: {
      const double h = dimension(spec, "height");
      for (const auto& p : pentagon_vertices(dimension(spec, "side"))) {
        v.push_back(p + Eigen::Vector3d(h / 2, 0, 0));
        v.push_back(p - Eigen::Vector3d(h / 2, 0, 0));
      }
      break;
    }
    default:
      break;
  }
  return v;
}

// How far a circle of radius r with unit normal `axis` reaches along d from its centre.
double disc_reach(const Eigen::Vector3d& d, const Eigen::Vector3d& axis, double r) {
  return r * d.cross(axis).norm();
}

}  // namespace

double support(const SolidSpec& spec, const Eigen::Vector3d& direction) {
  const Eigen::Vector3d& c = spec.pose.center;
  const Eigen::Vector3d axis = spec.pose.axes.row(0).transpose();
  switch (spec.kind) {
    case ShapeKind::sphere:
      return direction.dot(c) + dimension(spec, "radius") * direction.norm();
    case ShapeKind::cylinder:
      return direction.dot(c) + 0.5 * dimension(spec, "height") * std::abs(direction.dot(axis)) +
             disc_reach(direction, axis, dimension(spec, "radius"));
    case ShapeKind::cone: {
      const double base = direction.dot(c) + disc_reach(direction, axis, dimension(spec, "radius"));
      return std::max(base, direction.dot(c + dimension(spec, "height") * axis));
    }
    default: {
      double best = -std::numeric_limits<double>::infinity();
      for (const auto& q : local_vertices(spec))
        best = std::max(best, direction.dot(spec.pose.to_world(q)));
      return best;
    }
  }
}

double bounding_radius(const SolidSpec& spec) {
  switch (spec.kind) {
    case ShapeKind::sphere:
      return dimension(spec, "radius");
    case ShapeKind::cylinder:
      return std::hypot(dimension(spec, "radius"), dimension(spec, "height") / 2);
    case ShapeKind::cone:
      return std::max(dimension(spec, "radius"), dimension(spec, "height"));
    default: {
      double best = 0.0;
      for (const auto& q : local_vertices(spec)) best = std::max(best, q.norm());
      return best;
    }
  }
}

void translate(SolidSpec& spec, const Eigen::Vector3d& offset) { spec.pose.center += offset; }

}  // namespace cloudshape::synth
