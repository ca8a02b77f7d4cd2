#include "geometry/oriented_box.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/convex_hull.hpp"
#include "geometry/pca.hpp"

namespace cloudshape::geometry {
namespace {

using Vec2 = Eigen::Vector2d;

// The direction (unit, in the plane) of the minimum-area rectangle's first side: one side
// of the smallest enclosing rectangle always lies along a hull edge.
Vec2 min_area_direction(const std::vector<Vec2>& hull) {
  Vec2 best = Vec2::UnitX();
  double best_area = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    if (!(e.norm() > 0.0)) continue;
    const Vec2 u = e.normalized(), v(-u.y(), u.x());
    double ulo = HUGE_VAL, uhi = -HUGE_VAL, vlo = HUGE_VAL, vhi = -HUGE_VAL;
    for (const Vec2& q : hull) {
      ulo = std::min(ulo, q.dot(u)), uhi = std::max(uhi, q.dot(u));
      vlo = std::min(vlo, q.dot(v)), vhi = std::max(vhi, q.dot(v));
    }
    const double area = (uhi - ulo) * (vhi - vlo);
    if (area < best_area) best_area = area, best = u;
  }
  return best;
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
  const Vec2 d = min_area_direction(convex_hull_2d(hull_candidates(projected)));
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

OrientedBox oriented_bounding_box(const PointList& points, const std::vector<Eigen::Matrix3d>& hints,
                                  std::size_t hull_samples) {
  if (points.empty()) return {};
  // The frame is chosen on a sample; the bounds then take every point.
  const std::size_t step = std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, hull_samples));
  PointList sample;
  for (std::size_t i = 0; i < points.size(); i += step) sample.push_back(points[i]);
  std::vector<Eigen::Matrix3d> starts{orthonormal_rows(compute_pca(points).eigenvectors.transpose())};
  for (const Eigen::Matrix3d& h : hints)
    if (h.allFinite()) starts.push_back(orthonormal_rows(h));
  Eigen::Matrix3d best_frame = starts.front();
  double best_volume = std::numeric_limits<double>::infinity();
  // Principal axes are arbitrary on a cube-like set: from every start, each round turns the
  // frame about each of its axes to its tightest rectangle and keeps the best, until a round
  // gains nothing (a face of the tightest box then lies across one of the frame's axes).
  for (const Eigen::Matrix3d& start : starts) {
    Eigen::Matrix3d current = start;
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
    if (current_volume < best_volume) best_volume = current_volume, best_frame = current;
  }
  return sorted(box_in_frame(points, best_frame));
}

}  // namespace cloudshape::geometry
