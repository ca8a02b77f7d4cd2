#include "synth/surface_normal.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "synth/solid_geometry.hpp"

namespace cloudshape::synth {

namespace {

// Tracks the largest constraint value and its gradient, in the solid's local frame.
class ActiveConstraint {
 public:
  void offer(double value, const Eigen::Vector3d& gradient) {
    if (value > value_) value_ = value, gradient_ = gradient;
  }
  // A plane through a, b, c, oriented away from the local origin (inside every solid).
  void offer_plane(const Eigen::Vector3d& q, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                   const Eigen::Vector3d& c) {
    Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    if (n.dot(a) < 0.0) n = -n;
    offer(n.dot(q - a), n);
  }
  double value() const { return value_; }
  const Eigen::Vector3d& gradient() const { return gradient_; }

 private:
  double value_ = -std::numeric_limits<double>::infinity();
  Eigen::Vector3d gradient_ = Eigen::Vector3d::UnitX();
};

// Unit direction of (y, z) in the y-z plane; an arbitrary one on the axis itself.
Eigen::Vector3d radial(const Eigen::Vector3d& q) {
  const double rho = std::hypot(q.y(), q.z());
  return rho > 0.0 ? Eigen::Vector3d(0.0, q.y() / rho, q.z() / rho) : Eigen::Vector3d::UnitY();
}

ActiveConstraint local_constraint(const SolidSpec& spec, const Eigen::Vector3d& q) {
  ActiveConstraint active;
  const double rho = std::hypot(q.y(), q.z());
  switch (spec.kind) {
    case ShapeKind::box: {
      const Eigen::Vector3d half(dimension(spec, "length") / 2, dimension(spec, "width") / 2,
                                 dimension(spec, "height") / 2);
      for (int k = 0; k < 3; ++k)
        active.offer(std::abs(q[k]) - half[k], (q[k] < 0.0 ? -1.0 : 1.0) * Eigen::Vector3d::Unit(k));
      break;
    }
    case ShapeKind::tetrahedron: {
      const auto v = tetrahedron_vertices(dimension(spec, "edge"));
      for (int skip = 0; skip < 4; ++skip)
        active.offer_plane(q, v[(skip + 1) % 4], v[(skip + 2) % 4], v[(skip + 3) % 4]);
      break;
    }
    case ShapeKind::pentagonal_prism: {
      const double h = dimension(spec, "height");
      const auto v = pentagon_vertices(dimension(spec, "side"));
      active.offer(std::abs(q.x()) - h / 2, (q.x() < 0.0 ? -1.0 : 1.0) * Eigen::Vector3d::UnitX());
      for (int k = 0; k < 5; ++k)
        active.offer_plane(q, v[k], v[(k + 1) % 5], v[k] + Eigen::Vector3d::UnitX());
      break;
    }
    case ShapeKind::cone: {
      const double r = dimension(spec, "radius"), h = dimension(spec, "height");
      const double slant = std::hypot(r, h);
      active.offer(-q.x(), -Eigen::Vector3d::UnitX());
      // Distance to the lateral surface, measured along its normal.
      const Eigen::Vector3d n = (r / slant) * Eigen::Vector3d::UnitX() + (h / slant) * radial(q);
      active.offer((rho - r * (1.0 - q.x() / h)) * h / slant, n);
      break;
    }
    case ShapeKind::cylinder: {
      const double r = dimension(spec, "radius"), h = dimension(spec, "height");
      active.offer(std::abs(q.x()) - h / 2, (q.x() < 0.0 ? -1.0 : 1.0) * Eigen::Vector3d::UnitX());
      active.offer(rho - r, radial(q));
      break;
    }
    case ShapeKind::sphere: {
      const double n = q.norm();
      active.offer(n - dimension(spec, "radius"), n > 0.0 ? Eigen::Vector3d(q / n) : Eigen::Vector3d::UnitX());
      break;
    }
    default:
      throw std::invalid_argument("surface_contact: unsupported shape kind");
  }
  return active;
}

}  // namespace

SurfaceContact surface_contact(const SolidSpec& spec, const Eigen::Vector3d& world) {
  const ActiveConstraint active = local_constraint(spec, spec.pose.axes * (world - spec.pose.center));
  // Rows of pose.axes are the local axes in world coordinates: local -> world is the transpose.
  return {spec.pose.axes.transpose() * active.gradient(), active.value()};
}

bool segment_enters(const SolidSpec& spec, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                    double margin) {
  const auto f = [&](double t) { return surface_contact(spec, from + t * (to - from)).residual; };
  constexpr double kGolden = 0.6180339887498949;
  double a = 0.0, b = 1.0;
  double c = b - kGolden * (b - a), d = a + kGolden * (b - a);
  double fc = f(c), fd = f(d);
  for (int i = 0; i < 60 && b - a > 1e-9; ++i) {
    if (std::min(fc, fd) < -margin) return true;
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - kGolden * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + kGolden * (b - a), fd = f(d);
    }
  }
  return std::min(fc, fd) < -margin;
}

}  // namespace cloudshape::synth
