// Random prism cross-sections by kind: convex ones from angles on a (stretched) circle, the
// letter and star profiles from random arm widths; each normalised to unit extent about its centroid.
#include "synth/prism_section.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cloudshape::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Vec = Eigen::Vector2d;

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// n corners on an ellipse of axes 1 and `aspect`, turned by `turn`, every two at least
// `min_gap` radians apart around it.
geometry::Polygon2 on_ellipse(std::mt19937_64& rng, int n, double min_gap, double aspect) {
  std::vector<double> a;
  for (;;) {
    a.clear();
    for (int k = 0; k < n; ++k) a.push_back(uniform(rng, 0.0, 2.0 * kPi));
    std::sort(a.begin(), a.end());
    bool ok = true;
    for (int k = 0; k < n; ++k) {
      const double gap = k + 1 < n ? a[k + 1] - a[k] : a[0] + 2.0 * kPi - a[k];
      ok = ok && gap >= min_gap;
    }
    if (ok) break;
  }
  geometry::Polygon2 p;
  for (double t : a) p.emplace_back(std::cos(t), aspect * std::sin(t));
  return p;
}

geometry::Polygon2 raw_section(SectionKind kind, std::mt19937_64& rng) {
  switch (kind) {
    case SectionKind::triangle: return on_ellipse(rng, 3, 2.0 * kPi / 3.0 * 0.5, 1.0);
    case SectionKind::rhombus: {
      const double half = uniform(rng, 35.0, 75.0) * kPi / 360.0;  // half the acute corner
      return {Vec(std::cos(half), 0), Vec(0, std::sin(half)), Vec(-std::cos(half), 0), Vec(0, -std::sin(half))};
    }
    case SectionKind::regular_hexagon: {
      geometry::Polygon2 p;
      for (int k = 0; k < 6; ++k) p.emplace_back(std::cos(k * kPi / 3.0), std::sin(k * kPi / 3.0));
      return p;
    }
    case SectionKind::hexagon: {
      geometry::Polygon2 p;
      for (int k = 0; k < 6; ++k) {
        const double t = k * kPi / 3.0 + uniform(rng, -0.12, 0.12), r = uniform(rng, 0.85, 1.15);
        p.emplace_back(r * std::cos(t), r * std::sin(t));
      }
      return p;
    }
    case SectionKind::convex: {
      const int n = std::uniform_int_distribution<int>(3, 8)(rng);
      return on_ellipse(rng, n, 0.6 * 2.0 * kPi / n, uniform(rng, 0.6, 1.0));
    }
    case SectionKind::letter_l: {
      const double w = 1.0, h = uniform(rng, 0.8, 1.4), a = uniform(rng, 0.25, 0.5) * w, b = uniform(rng, 0.25, 0.5) * w;
      return {Vec(0, 0), Vec(w, 0), Vec(w, b), Vec(a, b), Vec(a, h), Vec(0, h)};
    }
    case SectionKind::letter_t: {
      const double w = 1.0, h = uniform(rng, 0.8, 1.3), bar = uniform(rng, 0.2, 0.4), s = 0.5 * uniform(rng, 0.2, 0.45);
      return {Vec(-s, 0), Vec(s, 0), Vec(s, h - bar), Vec(0.5 * w, h - bar), Vec(0.5 * w, h),
              Vec(-0.5 * w, h), Vec(-0.5 * w, h - bar), Vec(-s, h - bar)};
    }
    case SectionKind::plus: {
      const double x = 0.5, y = 0.5 * uniform(rng, 0.8, 1.2), a = 0.5 * uniform(rng, 0.25, 0.45), b = 0.5 * uniform(rng, 0.25, 0.45);
      return {Vec(a, -y), Vec(a, -b), Vec(x, -b), Vec(x, b), Vec(a, b), Vec(a, y),
              Vec(-a, y), Vec(-a, b), Vec(-x, b), Vec(-x, -b), Vec(-a, -b), Vec(-a, -y)};
    }
    case SectionKind::star: {
      const int points = std::uniform_int_distribution<int>(5, 6)(rng);
      const double inner = uniform(rng, 0.4, 0.6);
      geometry::Polygon2 p;
      for (int k = 0; k < 2 * points; ++k) {
        const double t = k * kPi / points, r = k % 2 == 0 ? 1.0 : inner;
        p.emplace_back(r * std::cos(t), r * std::sin(t));
      }
      return p;
    }
  }
  return {};
}

double turn_degrees(const geometry::Polygon2& p, std::size_t i) {
  const std::size_t n = p.size();
  const Vec a = p[i] - p[(i + n - 1) % n], b = p[(i + 1) % n] - p[i];
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)) * 180.0 / kPi;
}

}  // namespace

const std::vector<SectionKind>& all_section_kinds() {
  static const std::vector<SectionKind> kinds = {
      SectionKind::triangle, SectionKind::rhombus,  SectionKind::regular_hexagon,
      SectionKind::hexagon,  SectionKind::convex,   SectionKind::letter_l,
      SectionKind::letter_t, SectionKind::plus,     SectionKind::star};
  return kinds;
}

std::string to_string(SectionKind kind) {
  static const std::array<const char*, 9> names = {"triangle", "rhombus",  "regular_hexagon", "hexagon", "convex",
                                                   "letter_l", "letter_t", "plus",            "star"};
  return names[static_cast<std::size_t>(kind)];
}

PrismSection random_section(SectionKind kind, std::mt19937_64& rng) {
  for (;;) {
    geometry::Polygon2 p = raw_section(kind, rng);
    if (geometry::signed_area(p) < 0.0) std::reverse(p.begin(), p.end());
    const Vec c = geometry::area_centroid(p);
    double extent = 0.0;
    for (const Vec& a : p)
      for (const Vec& b : p) extent = std::max(extent, (a - b).norm());
    for (Vec& v : p) v = (v - c) / extent;
    bool ok = geometry::is_simple(p);
    for (std::size_t i = 0; i < p.size() && ok; ++i)
      ok = std::abs(turn_degrees(p, i)) >= 25.0 && (p[(i + 1) % p.size()] - p[i]).norm() >= 0.1;
    // A rectangle is a box and a regular pentagon a pentagonal prism: neither is drawn here
    // (the regular pentagon is out of reach of the kinds: no five equal corners).
    bool square_corners = p.size() == 4;
    for (std::size_t i = 0; i < p.size() && square_corners; ++i) square_corners = std::abs(turn_degrees(p, i) - 90.0) < 12.0;
    if (ok && !square_corners) return {kind, p, kind == SectionKind::regular_hexagon};
  }
}

}  // namespace cloudshape::synth
