// Simple 2-D polygons: area, centroid, signed distance, simplicity and ear clipping.
// The prism fitter verifies against signed_distance; synth and the markers cut caps with triangulate.
#include "geometry/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace cloudshape::geometry {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

bool inside_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                     const Eigen::Vector2d& c) {
  return cross(b - a, p - a) >= 0.0 && cross(c - b, p - b) >= 0.0 && cross(a - c, p - c) >= 0.0;
}

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

bool segments_cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    const Eigen::Vector2d& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

}  // namespace

Polygon2 regular_polygon(int sides, double circumradius, double first_angle) {
  constexpr double kTwoPi = 6.28318530717958647692;
  Polygon2 out;
  for (int k = 0; k < sides; ++k) {
    const double t = first_angle + kTwoPi * k / sides;
    out.emplace_back(circumradius * std::cos(t), circumradius * std::sin(t));
  }
  return out;
}

double signed_area(const Polygon2& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) twice += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * twice;
}

double perimeter(const Polygon2& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) sum += (polygon[(i + 1) % polygon.size()] - polygon[i]).norm();
  return sum;
}

Eigen::Vector2d area_centroid(const Polygon2& polygon) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : polygon) mean += p / static_cast<double>(std::max<std::size_t>(1, polygon.size()));
  // About the vertex mean, so that far from the origin no precision is lost.
  double twice_area = 0.0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i] - mean, b = polygon[(i + 1) % polygon.size()] - mean;
    const double c = cross(a, b);
    twice_area += c;
    sum += c * (a + b);
  }
  if (std::abs(twice_area) < 1e-300) return mean;
  return mean + sum / (3.0 * twice_area);
}

double signed_distance(const Polygon2& polygon, const Eigen::Vector2d& p) {
  double d = std::numeric_limits<double>::infinity();
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    d = std::min(d, segment_distance(p, a, b));
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside ? -d : d;
}

bool is_simple(const Polygon2& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
      if (segments_cross(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n])) return false;
    }
  return true;
}

std::vector<std::array<std::size_t, 3>> triangulate(const Polygon2& polygon) {
  std::vector<std::size_t> left(polygon.size());
  std::iota(left.begin(), left.end(), 0);
  std::vector<std::array<std::size_t, 3>> out;
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
      const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k], c = left[(k + 1) % left.size()];
      if (cross(polygon[b] - polygon[a], polygon[c] - polygon[b]) <= 0.0) continue;  // reflex: no ear
      const bool empty = std::none_of(left.begin(), left.end(), [&](std::size_t v) {
        return v != a && v != b && v != c && inside_triangle(polygon[v], polygon[a], polygon[b], polygon[c]);
      });
      if (!empty) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    if (!clipped) return out;
  }
  if (left.size() == 3) out.push_back({left[0], left[1], left[2]});
  return out;
}

}  // namespace cloudshape::geometry
