// A flat face's outline: occupied cells closed over small holes, the outer boundary traced by
// Moore-neighbour tracing, then Douglas-Peucker down to its corners.
#include "pipeline/prism_outline.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace cloudshape::pipeline::detail {
namespace {

struct Grid {
  int w = 0, h = 0;
  std::vector<char> on;
  bool at(int x, int y) const { return x >= 0 && y >= 0 && x < w && y < h && on[y * w + x]; }
};

// One-cell dilation then erosion: holes a cell wide (sparse sampling) close, corners stay.
Grid closed(const Grid& g) {
  Grid d = g, e = g;
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w; ++x) {
      bool any = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) any = any || g.at(x + dx, y + dy);
      d.on[y * g.w + x] = any;
    }
  for (int y = 0; y < g.h; ++y)
    for (int x = 0; x < g.w; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) all = all && d.at(x + dx, y + dy);
      e.on[y * g.w + x] = all;
    }
  return e;
}

// The outer boundary's cells in order, from the first occupied cell in raster order.
std::vector<std::array<int, 2>> trace(const Grid& g) {
  static const std::array<std::array<int, 2>, 8> dirs = {
      {{-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}}};
  int sx = -1, sy = -1;
  for (int y = 0; y < g.h && sx < 0; ++y)
    for (int x = 0; x < g.w; ++x)
      if (g.at(x, y)) {
        sx = x, sy = y;
        break;
      }
  std::vector<std::array<int, 2>> out;
  if (sx < 0) return out;
  int cx = sx, cy = sy, from = 0;  // the west neighbour of the start is empty
  const std::size_t limit = 4 * static_cast<std::size_t>(g.w + g.h) * 8;
  do {
    out.push_back({cx, cy});
    int k = 0;
    for (; k < 8; ++k) {
      const int d = (from + 1 + k) % 8;
      if (g.at(cx + dirs[d][0], cy + dirs[d][1])) {
        cx += dirs[d][0];
        cy += dirs[d][1];
        from = (d + 4) % 8;  // look around the next cell starting past where we came from
        break;
      }
    }
    if (k == 8) break;  // a single cell
  } while (!(cx == sx && cy == sy) && out.size() < limit);
  return out;
}

void simplify(const std::vector<Eigen::Vector2d>& p, std::size_t a, std::size_t b, double tolerance,
              std::vector<std::size_t>& keep) {
  if (b <= a + 1) return;
  const Eigen::Vector2d ab = p[b] - p[a];
  double worst = -1.0;
  std::size_t at = a;
  for (std::size_t i = a + 1; i < b; ++i) {
    const Eigen::Vector2d ap = p[i] - p[a];
    const double d = ab.norm() > 0 ? std::abs(ab.x() * ap.y() - ab.y() * ap.x()) / ab.norm() : ap.norm();
    if (d > worst) worst = d, at = i;
  }
  if (worst <= tolerance) return;
  simplify(p, a, at, tolerance, keep);
  keep.push_back(at);
  simplify(p, at, b, tolerance, keep);
}

}  // namespace

geometry::Polygon2 face_outline_polygon(const std::vector<Eigen::Vector2d>& points, double cell,
                                        double tolerance) {
  if (points.size() < 10 || !(cell > 0.0)) return {};
  Eigen::Vector2d lo = points.front(), hi = points.front();
  for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  Grid g;
  g.w = static_cast<int>((hi.x() - lo.x()) / cell) + 3;
  g.h = static_cast<int>((hi.y() - lo.y()) / cell) + 3;
  if (static_cast<double>(g.w) * g.h > 4.0e6) return {};
  g.on.assign(static_cast<std::size_t>(g.w * g.h), 0);
  for (const auto& p : points) {
    const int x = 1 + static_cast<int>((p.x() - lo.x()) / cell), y = 1 + static_cast<int>((p.y() - lo.y()) / cell);
    g.on[y * g.w + x] = 1;
  }
  const auto cells = trace(closed(g));
  if (cells.size() < 8) return {};
  std::vector<Eigen::Vector2d> contour;
  for (const auto& c : cells) contour.emplace_back(lo.x() + (c[0] - 0.5) * cell, lo.y() + (c[1] - 0.5) * cell);
  // Split the closed contour at its two mutually far points, simplify each half.
  std::size_t far = 0;
  for (std::size_t i = 0; i < contour.size(); ++i)
    if ((contour[i] - contour[0]).norm() > (contour[far] - contour[0]).norm()) far = i;
  contour.push_back(contour.front());
  std::vector<std::size_t> keep{0};
  simplify(contour, 0, far, tolerance, keep);
  keep.push_back(far);
  simplify(contour, far, contour.size() - 1, tolerance, keep);
  geometry::Polygon2 out;
  for (std::size_t k : keep) out.push_back(contour[k]);
  if (geometry::signed_area(out) < 0.0) std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace cloudshape::pipeline::detail
