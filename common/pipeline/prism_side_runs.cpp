#include "pipeline/prism_side_runs.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "geometry/convex_hull.hpp"
#include "geometry/polygon.hpp"

namespace cloudshape::pipeline::detail {

std::vector<SideRun> side_runs(const SolveInput& in, const DetectedPlane& face,
                               const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                               const std::vector<Eigen::Vector2d>& cap_points,
                               const std::vector<const DetectedPlane*>& caps) {
  Eigen::Vector2d n(face.plane.normal.dot(u), face.plane.normal.dot(v));
  if (!(n.norm() > 0.0)) return {};
  n.normalize();
  std::vector<Eigen::Vector2d> pts;
  std::vector<double> heights;
  pts.reserve(face.inliers.size());
  double d = 0.0;
  // A side's plane runs on across a cap at a concave corner (an L's inner faces), and its band
  // takes the cap's points there: points at a cap's height are left to the cap.
  const double cap_band = 2.0 * in.cfg.inlier_distance * in.resolution;
  for (std::uint32_t i : face.inliers) {
    bool on_cap = false;
    for (const DetectedPlane* c : caps) on_cap = on_cap || std::abs(c->plane.signed_distance(in.cloud[i])) < cap_band;
    if (on_cap) continue;
    pts.emplace_back(in.cloud[i].dot(u), in.cloud[i].dot(v));
    heights.push_back(in.cloud[i].dot(u.cross(v)));
    d += pts.back().dot(n);
  }
  d /= static_cast<double>(std::max<std::size_t>(1, pts.size()));
  const Eigen::Vector2d tangent(-n.y(), n.x());
  // (along the side, along the axis) of each point: the runs split on the first, their
  // rectangles are checked on both.
  std::vector<Eigen::Vector2d> ta;
  for (std::size_t k = 0; k < pts.size(); ++k) ta.emplace_back(pts[k].dot(tangent), heights[k]);
  std::sort(ta.begin(), ta.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() < b.x(); });
  std::vector<double> t;
  for (const auto& p : ta) t.push_back(p.x());
  const double gap = in.cfg.prism_run_gap * in.resolution;
  const std::size_t min_points = std::max<std::size_t>(8, face.inliers.size() / 50);
  std::vector<SideRun> runs;
  std::size_t first = 0;
  for (std::size_t k = 1; k <= t.size(); ++k) {
    if (k < t.size() && t[k] - t[k - 1] <= gap) continue;
    if (k - first >= min_points) {
      SideRun r;
      r.n = n;
      r.d = d;
      r.t_lo = t[first];
      r.t_hi = t[k - 1];
      r.weight = static_cast<double>(k - first);
      r.hull_area = std::abs(geometry::signed_area(geometry::convex_hull_2d(
          std::vector<Eigen::Vector2d>(ta.begin() + static_cast<std::ptrdiff_t>(first), ta.begin() + static_cast<std::ptrdiff_t>(k)))));
      runs.push_back(r);
    }
    first = k;
  }
  // Caps fill the outline: each run's inside is where the cap points beside it are.
  const double reach = std::max(in.cfg.prism_run_gap, 2.0 * in.cfg.inlier_distance) * in.resolution;
  const double band = in.cfg.inlier_distance * in.resolution;
  for (SideRun& r : runs) {
    std::size_t inside = 0, outside = 0;
    for (const auto& p : cap_points) {
      const double s = p.dot(r.n) - r.d, along = p.dot(r.tangent());
      if (along < r.t_lo || along > r.t_hi || std::abs(s) < band || std::abs(s) > reach + band) continue;
      ++(s < 0 ? inside : outside);
    }
    if (outside > inside && outside >= 4) {
      r.n = -r.n;
      r.d = -r.d;
      std::tie(r.t_lo, r.t_hi) = std::make_pair(-r.t_hi, -r.t_lo);
    }
  }
  return runs;
}

std::optional<std::vector<SideRun>> chain_runs(std::vector<SideRun> runs, double max_gap) {
  // Runs off the walk are what plane noise cuts from the edges between sides.
  if (runs.size() < 3) return std::nullopt;
  std::sort(runs.begin(), runs.end(), [](const SideRun& a, const SideRun& b) { return a.weight > b.weight; });
  std::vector<bool> taken(runs.size(), false);
  std::vector<SideRun> ordered{runs[0]};
  taken[0] = true;
  std::size_t at = 0;
  for (;;) {
    std::size_t next = runs.size();
    double best = max_gap;
    for (std::size_t j = 0; j < runs.size(); ++j) {
      if (j == at || (taken[j] && !(j == 0 && ordered.size() >= 3))) continue;
      const double g = (runs[at].end() - runs[j].start()).norm();
      if (g <= best) best = g, next = j;
    }
    if (next == runs.size()) return std::nullopt;
    if (next == 0) return ordered;
    taken[next] = true;
    ordered.push_back(runs[next]);
    at = next;
  }
}

std::vector<SideRun> merge_collinear(std::vector<SideRun> ring, double cos_parallel, double band,
                                     double loose_band) {
  bool merged = true;
  while (merged && ring.size() > 3) {
    merged = false;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const std::size_t j = (i + 1) % ring.size();
      const double allowed = ring[i].seen && ring[j].seen ? band : loose_band;
      if (ring[i].n.dot(ring[j].n) < cos_parallel || std::abs(ring[i].d - ring[j].d) > allowed) continue;
      SideRun m = ring[i];
      const double w = ring[i].weight + ring[j].weight;
      m.n = (ring[i].weight * ring[i].n + ring[j].weight * ring[j].n).normalized();
      m.d = (ring[i].weight * ring[i].d + ring[j].weight * ring[j].d) / w;
      m.t_lo = ring[i].start().dot(m.tangent());
      m.t_hi = ring[j].end().dot(m.tangent());
      m.weight = w;
      m.seen = ring[i].seen || ring[j].seen;
      ring[i] = m;
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(j));
      merged = true;
      break;
    }
  }
  return ring;
}

std::optional<Eigen::Vector2d> intersect(const SideRun& a, const SideRun& b) {
  Eigen::Matrix2d m;
  m.row(0) = a.n.transpose();
  m.row(1) = b.n.transpose();
  if (std::abs(m.determinant()) < 1e-9) return std::nullopt;
  return m.inverse() * Eigen::Vector2d(a.d, b.d);
}

}  // namespace cloudshape::pipeline::detail
