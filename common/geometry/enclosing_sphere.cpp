#include "geometry/enclosing_sphere.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>
#include <random>

#include "geometry/circle.hpp"

namespace cloudshape::geometry {
namespace {

bool outside(const Sphere& s, const Point& p) {
  // A relative tolerance keeps round-off from re-triggering on boundary points.
  return (p - s.center).norm() > s.radius * (1.0 + 1e-10) + 1e-12;
}

Sphere sphere_from(const Point& a, const Point& b) {
  return {0.5 * (a + b), 0.5 * (a - b).norm()};
}

Sphere sphere_from(const Point& a, const Point& b, const Point& c) {
  if (const auto circle = circumcircle(a, b, c)) return {circle->center, circle->radius};
  // Collinear: the two farthest apart span the sphere.
  Sphere best = sphere_from(a, b);
  for (const Sphere& s : {sphere_from(a, c), sphere_from(b, c)})
    if (s.radius > best.radius) best = s;
  return best;
}

Sphere sphere_from(const Point& a, const Point& b, const Point& c, const Point& d) {
  Eigen::Matrix3d m;
  m.row(0) = (b - a).transpose();
  m.row(1) = (c - a).transpose();
  m.row(2) = (d - a).transpose();
  const Eigen::Vector3d rhs(0.5 * (b - a).squaredNorm(), 0.5 * (c - a).squaredNorm(),
                            0.5 * (d - a).squaredNorm());
  const double scale = std::max({m.row(0).norm(), m.row(1).norm(), m.row(2).norm()});
  if (std::abs(m.determinant()) > 1e-12 * scale * scale * scale) {
    const Eigen::Vector3d offset = m.partialPivLu().solve(rhs);
    return {a + offset, offset.norm()};
  }
  // Coplanar support: the smallest sphere through three of them that holds the fourth.
  const Point pts[4] = {a, b, c, d};
  Sphere best{Point::Zero(), std::numeric_limits<double>::infinity()};
  for (int skip = 0; skip < 4; ++skip) {
    Point tri[3];
    for (int i = 0, k = 0; i < 4; ++i)
      if (i != skip) tri[k++] = pts[i];
    const Sphere s = sphere_from(tri[0], tri[1], tri[2]);
    if (!outside(s, pts[skip]) && s.radius < best.radius) best = s;
  }
  return best;
}

}  // namespace

Sphere minimal_enclosing_sphere(const PointList& input) {
  if (input.empty()) return {};
  std::vector<std::uint32_t> order(input.size());
  std::iota(order.begin(), order.end(), 0u);
  std::mt19937 rng(0x5eed);
  std::shuffle(order.begin(), order.end(), rng);
  auto at = [&](std::size_t i) -> const Point& { return input[order[i]]; };

  Sphere s{at(0), 0.0};
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (!outside(s, at(i))) continue;
    s = {at(i), 0.0};
    for (std::size_t j = 0; j < i; ++j) {
      if (!outside(s, at(j))) continue;
      s = sphere_from(at(i), at(j));
      for (std::size_t k = 0; k < j; ++k) {
        if (!outside(s, at(k))) continue;
        s = sphere_from(at(i), at(j), at(k));
        for (std::size_t l = 0; l < k; ++l) {
          if (!outside(s, at(l))) continue;
          s = sphere_from(at(i), at(j), at(k), at(l));
        }
      }
    }
  }
  return s;
}

}  // namespace cloudshape::geometry
