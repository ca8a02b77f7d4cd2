#include "synth/ground_truth.hpp"
#include "synth/solid_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace cloudshape::synth {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::array<Eigen::Vector3d, 4> tetrahedron_vertices(double edge) {
  const double height = edge * std::sqrt(2.0 / 3.0);
  const double circumradius_base = edge / std::sqrt(3.0);
  std::array<Eigen::Vector3d, 4> v;
  v[0] = {0.75 * height, 0.0, 0.0};
  for (int k = 0; k < 3; ++k) {
    const double a = 2.0 * kPi * k / 3.0;
    v[k + 1] = {-0.25 * height, circumradius_base * std::cos(a), circumradius_base * std::sin(a)};
  }
  return v;
}

double pentagon_circumradius(double side) { return side / (2.0 * std::sin(kPi / 5.0)); }

std::array<Eigen::Vector3d, 5> pentagon_vertices(double side) {
  const double r = pentagon_circumradius(side);
  std::array<Eigen::Vector3d, 5> v;
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * kPi * k / 5.0;
    v[k] = {0.0, r * std::cos(a), r * std::sin(a)};
  }
  return v;
}

double dimension(const SolidSpec& spec, std::string_view name) {
  for (const auto& [n, value] : spec.dimensions)
    if (n == name) return value;
  throw std::invalid_argument(to_string(spec.kind) + " has no dimension '" + std::string(name) +
                              "'");
}

SolidSpec make_solid(ShapeKind kind, const std::vector<double>& values, const Pose& pose) {
  const auto& names = dimension_names(kind);
  if (values.size() != names.size())
    throw std::invalid_argument(to_string(kind) + " needs " + std::to_string(names.size()) +
                                " dimension(s), got " + std::to_string(values.size()));
  for (double v : values)
    if (!std::isfinite(v) || v <= 0.0)
      throw std::invalid_argument(to_string(kind) + " dimensions must be positive and finite");

  SolidSpec spec;
  spec.kind = kind;
  spec.pose = pose;
  if (kind == ShapeKind::box) {
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return values[a] > values[b]; });
    Eigen::Matrix3d axes;
    for (int i = 0; i < 3; ++i) {
      spec.dimensions.emplace_back(names[i], values[order[i]]);
      axes.row(i) = pose.axes.row(order[i]);
    }
    // A row permutation can mirror the frame; box axis signs are free, so restore a rotation.
    if (axes.determinant() < 0.0) axes.row(2) *= -1.0;
    spec.pose.axes = axes;
  } else {
    for (std::size_t i = 0; i < names.size(); ++i)
      spec.dimensions.emplace_back(names[i], values[i]);
  }
  return spec;
}

double characteristic_size(const SolidSpec& spec) {
  switch (spec.kind) {
    case ShapeKind::box:
      return std::max(
          {dimension(spec, "length"), dimension(spec, "width"), dimension(spec, "height")});
    case ShapeKind::tetrahedron:
      return dimension(spec, "edge");
    case ShapeKind::pentagonal_prism:
      return std::max(2.0 * pentagon_circumradius(dimension(spec, "side")),
                      dimension(spec, "height"));
    case ShapeKind::cone:
    case ShapeKind::cylinder:
      return std::max(2.0 * dimension(spec, "radius"), dimension(spec, "height"));
    case ShapeKind::sphere:
      return 2.0 * dimension(spec, "radius");
  }
  return 0.0;
}

double surface_area(const SolidSpec& spec) {
  switch (spec.kind) {
    case ShapeKind::box: {
      const double l = dimension(spec, "length"), w = dimension(spec, "width"),
                   h = dimension(spec, "height");
      return 2.0 * (l * w + l * h + w * h);
    }
    case ShapeKind::tetrahedron: {
      const double e = dimension(spec, "edge");
      return std::sqrt(3.0) * e * e;
    }
    case ShapeKind::pentagonal_prism: {
      const double s = dimension(spec, "side"), h = dimension(spec, "height");
      const double r = pentagon_circumradius(s);
      return 2.0 * 2.5 * r * r * std::sin(2.0 * kPi / 5.0) + 5.0 * s * h;
    }
    case ShapeKind::cone: {
      const double r = dimension(spec, "radius"), h = dimension(spec, "height");
      return kPi * r * r + kPi * r * std::hypot(r, h);
    }
    case ShapeKind::cylinder: {
      const double r = dimension(spec, "radius"), h = dimension(spec, "height");
      return 2.0 * kPi * r * r + 2.0 * kPi * r * h;
    }
    case ShapeKind::sphere: {
      const double r = dimension(spec, "radius");
      return 4.0 * kPi * r * r;
    }
  }
  return 0.0;
}

}  // namespace cloudshape::synth
