#include "geometry/convex_hull.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cloudshape::geometry {
namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

std::vector<Vec2> hull_candidates(const std::vector<Vec2>& points) {
  if (points.size() < 32) return points;
  // Extremes along 0, 45, ..., 315 degrees, so that the octagon runs counter-clockwise. Any
  // closed chain of the set's points would do as its outline (a point left of all of its edges is
  // wound round, so inside their hull, convex or not): the extremes of every second point give
  // nearly the whole octagon.
  constexpr std::size_t kStride = 2;
  std::array<std::size_t, 8> at{};
  double x0 = -HUGE_VAL, x1 = -HUGE_VAL, x2 = -HUGE_VAL, x3 = -HUGE_VAL;
  double x4 = -HUGE_VAL, x5 = -HUGE_VAL, x6 = -HUGE_VAL, x7 = -HUGE_VAL;
  for (std::size_t i = 0; i < points.size(); i += kStride) {
    const double x = points[i].x(), y = points[i].y(), s = x + y, d = x - y;
    if (x > x0) x0 = x, at[0] = i;
    if (s > x1) x1 = s, at[1] = i;
    if (y > x2) x2 = y, at[2] = i;
    if (-d > x3) x3 = -d, at[3] = i;
    if (-x > x4) x4 = -x, at[4] = i;
    if (-s > x5) x5 = -s, at[5] = i;
    if (-y > x6) x6 = -y, at[6] = i;
    if (d > x7) x7 = d, at[7] = i;
  }
  if (!std::isfinite(x0 + x2 + x4 + x6)) return points;
  const double extent = std::max(x0 + x4, x2 + x6);
  const double magnitude =
      std::max(std::max(std::abs(x0), std::abs(x4)), std::max(std::abs(x2), std::abs(x6)));
  // A cross product's rounding is a few ulps of (extent + magnitude) * extent; the margin is far
  // above it, so a point dropped is inside the hull whatever the rounding.
  const double margin = 1e-9 * extent * (extent + magnitude);
  // Edges as lines a x + b y + c, positive inside, between the corners `step` apart; a repeated
  // corner gives no edge.
  struct Lines {
    std::array<double, 8> a{}, b{}, c{};
    int count = 0;
  };
  auto lines = [&](int first, int step) {
    Lines out;
    for (int k = first; k < 8; k += step) {
      const Vec2& o = points[at[k]];
      const Vec2& e = points[at[(k + step) % 8]];
      if (o == e) continue;
      out.a[out.count] = o.y() - e.y(), out.b[out.count] = e.x() - o.x();
      out.c[out.count] = -(out.a[out.count] * o.x() + out.b[out.count] * o.y());
      ++out.count;
    }
    return out;
  };
  const Lines octagon = lines(0, 1);
  if (octagon.count < 3) return points;
  // Most inner points fall inside one of the octagon's two quadrilaterals (the one of the axis
  // extremes holds a rotated rectangle, the diagonal one an upright one): four tests, not eight.
  auto area = [&](int first) {
    double twice = 0.0;
    for (int k = first; k < 8; k += 2) {
      const Vec2& o = points[at[k]];
      const Vec2& e = points[at[(k + 2) % 8]];
      twice += o.x() * e.y() - o.y() * e.x();
    }
    return twice;
  };
  Lines quad = lines(area(0) >= area(1) ? 0 : 1, 2);
  // A repeated corner's missing edge is a line every point passes (the others still close the
  // chain); with no edge at all no point is inside.
  for (int k = quad.count; k < 4; ++k)
    quad.a[k] = 0.0, quad.b[k] = 0.0, quad.c[k] = quad.count > 0 ? HUGE_VAL : -HUGE_VAL;
  std::vector<Vec2> out;
  out.reserve(points.size() / 2);
  for (const Vec2& q : points) {
    const double x = q.x(), y = q.y();
    const bool in_quad = (quad.a[0] * x + quad.b[0] * y + quad.c[0] > margin) &
                         (quad.a[1] * x + quad.b[1] * y + quad.c[1] > margin) &
                         (quad.a[2] * x + quad.b[2] * y + quad.c[2] > margin) &
                         (quad.a[3] * x + quad.b[3] * y + quad.c[3] > margin);
    if (in_quad) continue;
    bool in_octagon = true;
    for (int k = 0; k < octagon.count && in_octagon; ++k)
      in_octagon = octagon.a[k] * x + octagon.b[k] * y + octagon.c[k] > margin;
    if (!in_octagon) out.push_back(q);
  }
  return out;
}

std::vector<Vec2> convex_hull_2d(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace cloudshape::geometry
