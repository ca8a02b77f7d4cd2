#include "synth/sample_solid.hpp"
#include "synth/solid_geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace cloudshape::synth {

namespace {

constexpr double kPi = 3.14159265358979323846;

using Uniform = std::uniform_real_distribution<double>;

// Chooses a patch index with probability proportional to its area.
template <std::size_t N>
class PatchPicker {
 public:
  explicit PatchPicker(const std::array<double, N>& areas) {
    double sum = 0.0;
    for (std::size_t i = 0; i < N; ++i) cumulative_[i] = (sum += areas[i]);
  }
  std::size_t pick(double u01) const {
    const double target = u01 * cumulative_[N - 1];
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
    return std::min<std::size_t>(static_cast<std::size_t>(it - cumulative_.begin()), N - 1);
  }

 private:
  std::array<double, N> cumulative_{};
};

// Uniform point in triangle abc; the square root undoes the density bias towards vertex a.
Eigen::Vector3d in_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c, double u1, double u2) {
  const double s = std::sqrt(u1);
  return (1.0 - s) * a + s * (1.0 - u2) * b + s * u2 * c;
}

// Uniform point on a disk of radius r in the y-z plane at the given x.
Eigen::Vector3d in_disk(double x, double r, double u1, double u2) {
  const double rho = r * std::sqrt(u1);
  const double phi = 2.0 * kPi * u2;
  return {x, rho * std::cos(phi), rho * std::sin(phi)};
}

void check_positive(const SolidSpec& spec) {
  for (const auto& [name, value] : spec.dimensions)
    if (!std::isfinite(value) || value <= 0.0)
      throw std::invalid_argument(to_string(spec.kind) + " dimension '" + name +
                                  "' must be positive and finite");
}

template <typename LocalSampler>
PointList sample_posed(const Pose& pose, std::size_t n, std::mt19937_64& rng, LocalSampler&& f) {
  PointList out;
  out.reserve(n);
  const Eigen::Matrix3d to_world = pose.axes.transpose();
  Uniform u(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = u(rng), b = u(rng), c = u(rng);
    out.push_back(pose.center + to_world * f(a, b, c));
  }
  return out;
}

PointList sample_box(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng) {
  const Eigen::Vector3d half(dimension(spec, "length") / 2, dimension(spec, "width") / 2,
                             dimension(spec, "height") / 2);
  // Patch 2k and 2k+1 are the two faces normal to local axis k.
  const double ayz = 4 * half.y() * half.z(), axz = 4 * half.x() * half.z(),
               axy = 4 * half.x() * half.y();
  const PatchPicker<6> picker({ayz, ayz, axz, axz, axy, axy});
  return sample_posed(spec.pose, n, rng, [&](double a, double b, double c) {
    const std::size_t patch = picker.pick(a);
    const int k = static_cast<int>(patch / 2);
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    Eigen::Vector3d p;
    p[k] = (patch % 2 == 0) ? half[k] : -half[k];
    p[i] = (2 * b - 1) * half[i];
    p[j] = (2 * c - 1) * half[j];
    return p;
  });
}

PointList sample_tetrahedron(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng) {
  const auto v = tetrahedron_vertices(dimension(spec, "edge"));
  static constexpr std::array<std::array<int, 3>, 4> faces{
      {{1, 2, 3}, {0, 1, 2}, {0, 2, 3}, {0, 3, 1}}};
  return sample_posed(spec.pose, n, rng, [&](double a, double b, double c) {
    // Faces are congruent, so pick one uniformly by scaling a to [0, 4).
    const auto f = faces[std::min(static_cast<int>(a * 4.0), 3)];
    return in_triangle(v[f[0]], v[f[1]], v[f[2]], b, c);
  });
}

PointList sample_pentagonal_prism(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng) {
  const double side = dimension(spec, "side"), h = dimension(spec, "height");
  const auto pent = pentagon_vertices(side);
  const double r = pentagon_circumradius(side);
  const double cap = 2.5 * r * r * std::sin(2.0 * kPi / 5.0);
  const PatchPicker<3> picker({cap, cap, 5.0 * side * h});
  return sample_posed(spec.pose, n, rng, [&](double a, double b, double c) -> Eigen::Vector3d {
    const std::size_t patch = picker.pick(a);
    // Reuse the leftover of `b` to pick among five equal sectors / rectangles.
    const double b5 = b * 5.0;
    const int k = std::min(static_cast<int>(b5), 4);
    const double b_rest = b5 - k;
    const Eigen::Vector3d& p0 = pent[k];
    const Eigen::Vector3d& p1 = pent[(k + 1) % 5];
    if (patch == 2) {
      Eigen::Vector3d p = p0 + b_rest * (p1 - p0);
      p.x() = (c - 0.5) * h;
      return p;
    }
    Eigen::Vector3d p = in_triangle(Eigen::Vector3d::Zero(), p0, p1, b_rest, c);
    p.x() = patch == 0 ? h / 2 : -h / 2;
    return p;
  });
}

PointList sample_cone(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng) {
  const double r = dimension(spec, "radius"), h = dimension(spec, "height");
  const PatchPicker<2> picker({kPi * r * r, kPi * r * std::hypot(r, h)});
  return sample_posed(spec.pose, n, rng, [&](double a, double b, double c) -> Eigen::Vector3d {
    if (picker.pick(a) == 0) return in_disk(0.0, r, b, c);
    // Lateral area grows linearly with the distance t from the apex, so t ~ sqrt(U).
    const double t = std::sqrt(b);
    const double phi = 2.0 * kPi * c;
    return {h * (1.0 - t), r * t * std::cos(phi), r * t * std::sin(phi)};
  });
}

PointList sample_cylinder(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng) {
  const double r = dimension(spec, "radius"), h = dimension(spec, "height");
  const PatchPicker<3> picker({kPi * r * r, kPi * r * r, 2.0 * kPi * r * h});
  return sample_posed(spec.pose, n, rng, [&](double a, double b, double c) -> Eigen::Vector3d {
    switch (picker.pick(a)) {
      case 0:
        return in_disk(h / 2, r, b, c);
      case 1:
        return in_disk(-h / 2, r, b, c);
      default: {
        const double phi = 2.0 * kPi * c;
        return {(b - 0.5) * h, r * std::cos(phi), r * std::sin(phi)};
      }
    }
  });
}

PointList sample_sphere(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng) {
  const double r = dimension(spec, "radius");
  // Archimedes: on a sphere, the axial coordinate is uniform for area-uniform points.
  return sample_posed(spec.pose, n, rng, [&](double, double b, double c) -> Eigen::Vector3d {
    const double x = 2.0 * b - 1.0;
    const double rho = std::sqrt(std::max(0.0, 1.0 - x * x));
    const double phi = 2.0 * kPi * c;
    return r * Eigen::Vector3d(x, rho * std::cos(phi), rho * std::sin(phi));
  });
}

}  // namespace

PointList sample_solid_surface(const SolidSpec& spec, std::size_t n, std::mt19937_64& rng) {
  check_positive(spec);
  switch (spec.kind) {
    case ShapeKind::box:
      return sample_box(spec, n, rng);
    case ShapeKind::tetrahedron:
      return sample_tetrahedron(spec, n, rng);
    case ShapeKind::pentagonal_prism:
      return sample_pentagonal_prism(spec, n, rng);
    case ShapeKind::cone:
      return sample_cone(spec, n, rng);
    case ShapeKind::cylinder:
      return sample_cylinder(spec, n, rng);
    case ShapeKind::sphere:
      return sample_sphere(spec, n, rng);
  }
  throw std::invalid_argument("unsupported shape kind");
}

}  // namespace cloudshape::synth
