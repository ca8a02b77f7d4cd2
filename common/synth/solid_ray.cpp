// Ray against a convex solid: the solid's surface constraint (surface_contact) is convex along any
// line, so a golden-section search finds where the ray goes deepest and a bisection the entry.
#include "synth/solid_ray.hpp"

#include <algorithm>
#include <cmath>

#include "synth/surface_normal.hpp"

namespace cloudshape::synth {

std::optional<double> first_hit(const SolidSpec& spec, double radius, const Eigen::Vector3d& origin,
                                const Eigen::Vector3d& direction, double t_near, double t_far) {
  // Clip to the bounding sphere, slightly enlarged so its surface is strictly outside the solid.
  const Eigen::Vector3d to_centre = spec.pose.center - origin;
  const double along = to_centre.dot(direction);
  const double r = 1.01 * radius;
  const double miss2 = to_centre.squaredNorm() - along * along;
  if (miss2 >= r * r) return std::nullopt;
  const double half = std::sqrt(r * r - miss2);
  double a = std::max(t_near, along - half), b = std::min(t_far, along + half);
  if (!(a < b)) return std::nullopt;

  const auto g = [&](double t) { return surface_contact(spec, origin + t * direction).residual; };
  // Depth below which the ray counts as entering: rounding level of the solid's size.
  const double inside = -1e-12 * radius;
  const double start = a;
  if (g(start) < 0.0) return start;  // the ray begins inside: t_near is the first surface point
  constexpr double kGolden = 0.6180339887498949;
  double c = b - kGolden * (b - a), d = a + kGolden * (b - a);
  double gc = g(c), gd = g(d);
  for (int i = 0; i < 200 && gc >= inside && gd >= inside && b - a > 1e-15 * radius; ++i) {
    if (gc < gd) {
      b = d, d = c, gd = gc;
      c = b - kGolden * (b - a), gc = g(c);
    } else {
      a = c, c = d, gc = gd;
      d = a + kGolden * (b - a), gd = g(d);
    }
  }
  double deep;
  if (gc < inside)
    deep = c;
  else if (gd < inside)
    deep = d;
  else
    return std::nullopt;
  double lo = start, hi = deep;  // g(lo) >= 0 > g(hi)
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) >= 0.0 ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace cloudshape::synth
