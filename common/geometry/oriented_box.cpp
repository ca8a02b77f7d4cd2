#include "geometry/oriented_box.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/convex_hull.hpp"
#include "geometry/pca.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::geometry {
namespace {

using Vec2 = Eigen::Vector2d;

// Edge i of a closed polygon as a rectangle's first side: its unit direction u and the normal v
// turned from it counter-clockwise; none for an edge of no length.
bool edge_frame(const std::vector<Vec2>& hull, std::size_t i, Vec2& u, Vec2& v) {
  const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
  if (!(e.norm() > 0.0)) return false;
  u = e.normalized();
  v = Vec2(-u.y(), u.x());
  return true;
}

// The area of the rectangle along u and v round every hull point.
double rectangle_area(const std::vector<Vec2>& hull, const Vec2& u, const Vec2& v) {
  double ulo = HUGE_VAL, uhi = -HUGE_VAL, vlo = HUGE_VAL, vhi = -HUGE_VAL;
  for (const Vec2& q : hull) {
    ulo = std::min(ulo, q.dot(u)), uhi = std::max(uhi, q.dot(u));
    vlo = std::min(vlo, q.dot(v)), vhi = std::max(vhi, q.dot(v));
  }
  return (uhi - ulo) * (vhi - vlo);
}

// Each edge's rectangle_area from four extreme points only, found by rotating calipers: each
// moves on round the polygon while the next point lies at least as far out. The extremes are
// some of the points, so no width exceeds the true one, and (rounding is monotone) no area
// either: a lower bound of each edge's area, equal to it on a convex polygon but for rounding.
// NaN for an edge of no length.
std::vector<double> caliper_areas(const std::vector<Vec2>& hull) {
  const std::size_t n = hull.size();
  std::vector<double> lower(n, std::numeric_limits<double>::quiet_NaN());
  std::array<std::size_t, 4> at{};  // the points farthest along u, -u, v, -v
  bool placed = false;
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 u = Vec2::UnitX(), v = Vec2::UnitY();
    if (!edge_frame(hull, i, u, v)) continue;
    const std::array<Vec2, 4> along{u, Vec2(-u), v, Vec2(-v)};
    for (int k = 0; k < 4; ++k) {
      if (!placed) {
        for (std::size_t j = 1; j < n; ++j) {
          if (hull[j].dot(along[k]) > hull[at[k]].dot(along[k])) at[k] = j;
        }
      }
      for (std::size_t steps = 0; steps < n && hull[(at[k] + 1) % n].dot(along[k]) >= hull[at[k]].dot(along[k]);
           ++steps) {
        at[k] = (at[k] + 1) % n;
      }
    }
    placed = true;
    const double width_u = std::max(0.0, hull[at[0]].dot(u) - hull[at[1]].dot(u));
    const double width_v = std::max(0.0, hull[at[2]].dot(v) - hull[at[3]].dot(v));
    lower[i] = width_u * width_v;
  }
  return lower;
}

Eigen::Matrix3d orthonormal_rows(const Eigen::Matrix3d& m) {
  Eigen::Matrix3d out;
  out.row(0) = m.row(0).normalized();
  Eigen::Vector3d y = m.row(1).transpose();
  y -= y.dot(out.row(0).transpose()) * out.row(0).transpose();
  out.row(1) = y.normalized().transpose();
  out.row(2) = out.row(0).cross(out.row(1)).normalized();
  return out;
}

OrientedBox box_in_frame(const PointList& points, const Eigen::Matrix3d& frame) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
  for (const Point& p : points) {
    const Eigen::Vector3d l = frame * p;
    lo = lo.cwiseMin(l), hi = hi.cwiseMax(l);
  }
  OrientedBox box;
  box.axes = frame;
  box.size = hi - lo;
  box.center = frame.transpose() * (0.5 * (lo + hi));
  return box;
}

// Sizes descending, the frame kept right-handed (a swap of two rows flips the third).
OrientedBox sorted(OrientedBox b) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return b.size[x] > b.size[y]; });
  OrientedBox out = b;
  for (int i = 0; i < 3; ++i) out.axes.row(i) = b.axes.row(order[i]), out.size[i] = b.size[order[i]];
  if (out.axes.determinant() < 0.0) out.axes.row(2) *= -1.0;
  return out;
}

// The frame whose axis `a` is `frame`'s and whose other two axes are the minimum-area
// rectangle of the points projected across it.
Eigen::Matrix3d rectangle_frame(const PointList& points, const Eigen::Matrix3d& frame, int a) {
  const Eigen::Vector3d up = frame.row(a).transpose();
  const Eigen::Vector3d e1 = frame.row((a + 1) % 3).transpose();
  const Eigen::Vector3d e2 = up.cross(e1);
  std::vector<Vec2> projected;
  projected.reserve(points.size());
  for (const Point& p : points) projected.emplace_back(p.dot(e1), p.dot(e2));
  const Vec2 d = detail::min_area_direction(convex_hull_2d(hull_candidates(projected)));
  Eigen::Matrix3d f;
  f.row(0) = (d.x() * e1 + d.y() * e2).transpose();
  f.row(1) = up.cross(f.row(0).transpose()).transpose();
  f.row(2) = up.transpose();
  return orthonormal_rows(f);
}

// A flat set has no volume in any frame that holds its plane: a tiny term of the box's
// scale (same unit, cubed) still prefers the tighter rectangle there.
double volume(const OrientedBox& b) { return b.size.prod() + 1e-9 * std::pow(b.size.sum(), 3); }

}  // namespace

OrientedBox oriented_bounding_box(const PointList& points,
                                  const std::vector<Eigen::Matrix3d>& hints,
                                  std::size_t hull_samples, parallel::ThreadPool* pool) {
  if (points.empty()) return {};
  // The frame is chosen on a sample; the bounds then take every point.
  const std::size_t step = std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, hull_samples));
  PointList sample;
  for (std::size_t i = 0; i < points.size(); i += step) sample.push_back(points[i]);
  std::vector<Eigen::Matrix3d> starts{orthonormal_rows(compute_pca(points).eigenvectors.transpose())};
  for (const Eigen::Matrix3d& h : hints)
    if (h.allFinite()) starts.push_back(orthonormal_rows(h));
  // Principal axes are arbitrary on a cube-like set: from every start, each round turns the
  // frame about each of its axes to its tightest rectangle and keeps the best, until a round
  // gains nothing (a face of the tightest box then lies across one of the frame's axes). The
  // starts side by side on the pool; the first of the least volume wins, as in start order.
  std::vector<Eigen::Matrix3d> frame_of(starts.size());
  std::vector<double> volume_of(starts.size());
  parallel::for_blocks(pool, starts.size(), 1, [&](std::size_t s, std::size_t) {
    Eigen::Matrix3d current = starts[s];
    double current_volume = volume(box_in_frame(sample, current));
    for (int round = 0; round < 6; ++round) {
      Eigen::Matrix3d next = current;
      double next_volume = current_volume;
      for (int a = 0; a < 3; ++a) {
        const Eigen::Matrix3d f = rectangle_frame(sample, current, a);
        const double v = volume(box_in_frame(sample, f));
        if (v < next_volume) next_volume = v, next = f;
      }
      if (!(next_volume < current_volume * (1.0 - 1e-9))) break;
      current = next, current_volume = next_volume;
    }
    frame_of[s] = current;
    volume_of[s] = current_volume;
  });
  Eigen::Matrix3d best_frame = starts.front();
  double best_volume = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < starts.size(); ++s) {
    if (volume_of[s] < best_volume) best_volume = volume_of[s], best_frame = frame_of[s];
  }
  return sorted(box_in_frame(points, best_frame));
}

namespace detail {

// One side of the smallest enclosing rectangle always lies along a hull edge. The areas are
// those of every point, as a scan of every edge gives them, but worked out only for the edges
// whose caliper bound is at most the least area so far (in increasing order of bound): any other
// is larger than the least. So the same edge as that scan, in O(n log n) instead of O(n^2).
Eigen::Vector2d min_area_direction(const std::vector<Eigen::Vector2d>& hull) {
  const std::vector<double> lower = caliper_areas(hull);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    if (!std::isnan(lower[i])) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lower[a] < lower[b]; });
  std::vector<double> area(hull.size(), std::numeric_limits<double>::quiet_NaN());
  double least = HUGE_VAL;
  for (std::size_t i : order) {
    if (lower[i] > least) break;
    Vec2 u = Vec2::UnitX(), v = Vec2::UnitY();
    edge_frame(hull, i, u, v);
    area[i] = rectangle_area(hull, u, v);
    least = std::min(least, area[i]);
  }
  Vec2 best = Vec2::UnitX();
  double best_area = HUGE_VAL;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    if (!(area[i] < best_area)) continue;
    Vec2 v = Vec2::UnitY();
    edge_frame(hull, i, best, v);
    best_area = area[i];
  }
  return best;
}

}  // namespace detail

}  // namespace cloudshape::geometry
