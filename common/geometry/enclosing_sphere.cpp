#include "geometry/enclosing_sphere.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geometry/circle.hpp"

namespace cloudshape::geometry {

namespace detail {

bool outside(const Sphere& s, const Point& p) {
  // A relative tolerance keeps round-off from re-triggering on boundary points.
  return (p - s.center).norm() > s.radius * (1.0 + 1e-10) + 1e-12;
}

// The first of points [begin, end) outside s (outside's answer for each), or end. Most points
// are settled by their squared distance against the threshold's square widened by a millionth
// either way (far beyond any rounding of either side); only those within that band take the
// exact test. The incremental loops spend most of their time in these scans.
std::size_t first_outside(const Sphere& s, const PointList& points, std::size_t begin,
                          std::size_t end) {
  const double threshold = s.radius * (1.0 + 1e-10) + 1e-12;
  const double inside_below = threshold * threshold * (1.0 - 1e-6);
  const double outside_above = threshold * threshold * (1.0 + 1e-6);
  if (!std::isfinite(outside_above)) {
    for (std::size_t i = begin; i < end; ++i) {
      if (outside(s, points[i])) return i;
    }
    return end;
  }
  const auto settle = [&](std::size_t i, double d2) {
    return d2 >= outside_above || (d2 > inside_below && outside(s, points[i]));
  };
  std::size_t i = begin;
#if defined(__SSE2__)
  // Two points at a time: a pair both well inside (most) costs one branch.
  const __m128d cx = _mm_set1_pd(s.center.x()), cy = _mm_set1_pd(s.center.y()),
                cz = _mm_set1_pd(s.center.z());
  const __m128d below = _mm_set1_pd(inside_below);
  for (; i + 2 <= end; i += 2) {
    const Point& a = points[i];
    const Point& b = points[i + 1];
    const __m128d dx = _mm_sub_pd(_mm_set_pd(b.x(), a.x()), cx);
    const __m128d dy = _mm_sub_pd(_mm_set_pd(b.y(), a.y()), cy);
    const __m128d dz = _mm_sub_pd(_mm_set_pd(b.z(), a.z()), cz);
    const __m128d d2 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
    if (_mm_movemask_pd(_mm_cmple_pd(d2, below)) == 3) continue;
    alignas(16) double lane[2];
    _mm_store_pd(lane, d2);
    if (settle(i, lane[0])) return i;
    if (settle(i + 1, lane[1])) return i + 1;
  }
#endif
  for (; i < end; ++i) {
    const Eigen::Vector3d d = points[i] - s.center;
    if (settle(i, d.x() * d.x() + d.y() * d.y() + d.z() * d.z())) return i;
  }
  return end;
}

}  // namespace detail

namespace {

using detail::first_outside;
using detail::outside;

Sphere sphere_from(const Point& a, const Point& b) { return {0.5 * (a + b), 0.5 * (a - b).norm()}; }

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
  // The points in a fixed pseudo-random order, side by side: the scans read them in sequence.
  PointList at(input.size());
  {
    std::vector<std::uint32_t> order(input.size());
    std::iota(order.begin(), order.end(), 0u);
    std::mt19937 rng(0x5eed);
    std::shuffle(order.begin(), order.end(), rng);
    for (std::size_t i = 0; i < at.size(); ++i) at[i] = input[order[i]];
  }

  Sphere s{at[0], 0.0};
  for (std::size_t i = first_outside(s, at, 1, at.size()); i < at.size();
       i = first_outside(s, at, i + 1, at.size())) {
    s = {at[i], 0.0};
    for (std::size_t j = first_outside(s, at, 0, i); j < i; j = first_outside(s, at, j + 1, i)) {
      s = sphere_from(at[i], at[j]);
      for (std::size_t k = first_outside(s, at, 0, j); k < j; k = first_outside(s, at, k + 1, j)) {
        s = sphere_from(at[i], at[j], at[k]);
        for (std::size_t l = first_outside(s, at, 0, k); l < k;
             l = first_outside(s, at, l + 1, k)) {
          s = sphere_from(at[i], at[j], at[k], at[l]);
        }
      }
    }
  }
  return s;
}

}  // namespace cloudshape::geometry
