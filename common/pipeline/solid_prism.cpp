// Right prism of any simple cross-section (convex or not) from its faces: the axis from the
// side faces (perpendicular to it) and caps (along it); the outline from the side faces' lines,
// or from a cap's outline where sides are hidden (a single view).
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "geometry/convex_hull.hpp"
#include "geometry/polygon.hpp"
#include "pipeline/prism_outline.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One straight stretch of a side face in the cross-section plane: the line n.x = d with n
// outward, its points between t_lo and t_hi along the counter-clockwise tangent (-n.y, n.x).
struct SideRun {
  Eigen::Vector2d n = Eigen::Vector2d::UnitX();
  double d = 0.0;
  double t_lo = 0.0, t_hi = 0.0;
  double weight = 0.0;  // points behind the line
  bool seen = true;     // a side face's; false for a side only a cap's border shows
  double hull_area = 0.0;  // of its points in the plane of the side and the axis
  std::vector<Eigen::Vector2d> border;  // an unseen side's: the cap's border points its line is fitted to
  Eigen::Vector2d tangent() const { return {-n.y(), n.x()}; }
  Eigen::Vector2d start() const { return d * n + t_lo * tangent(); }
  Eigen::Vector2d end() const { return d * n + t_hi * tangent(); }
};

struct AxisChoice {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::vector<const DetectedPlane*> sides, caps;
  std::size_t points = 0;
};

// A right prism has two cap planes, at its two ends: a face along the axis anywhere between
// them (the inner step of an L seen along one of its arms) says the axis is another.
bool caps_at_ends(const SolveInput& in, const AxisChoice& c) {
  if (c.caps.empty()) return true;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Point& p : in.cloud) {
    lo = std::min(lo, p.dot(c.axis));
    hi = std::max(hi, p.dot(c.axis));
  }
  const double band = std::max(in.cfg.cap_band * in.resolution, in.cfg.face_slab * (hi - lo));
  for (const DetectedPlane* f : c.caps) {
    const double at = detail::face_position(in.cloud, *f, c.axis);
    const bool up = f->plane.normal.dot(c.axis) > 0;
    if (std::abs(at - (up ? hi : lo)) > band) return false;
  }
  return true;
}

// Axis hypotheses: every face's normal (a cap) and every two faces' common perpendicular (two
// sides). Three sides give an outline of their own: the hypothesis whose sides and caps hold most
// points is tried first. With fewer sides only a cap can (its traced border, ring_from_cap), so
// each face's normal with one or two sides follows, most points first: a view of a cap and one
// side has two such readings (either face the cap), and the outline decides between them.
std::vector<AxisChoice> choose_axes(const SolveInput& in, const std::vector<const DetectedPlane*>& faces) {
  const config::SolveConfig& cfg = in.cfg;
  const double sin_perp = std::sin(cfg.perpendicular_degrees * kPi / 180.0);
  const double cos_parallel = std::cos(cfg.parallel_degrees * kPi / 180.0);
  std::vector<std::pair<Eigen::Vector3d, bool>> hypotheses;  // (axis, along a face's normal)
  const std::size_t n = std::min<std::size_t>(faces.size(), 16);
  for (std::size_t i = 0; i < n; ++i) {
    hypotheses.emplace_back(faces[i]->plane.normal, true);
    for (std::size_t j = i + 1; j < n; ++j) {
      const Eigen::Vector3d c = faces[i]->plane.normal.cross(faces[j]->plane.normal);
      if (c.norm() > sin_perp) hypotheses.emplace_back(c.normalized(), false);
    }
  }
  std::optional<AxisChoice> best;
  std::vector<AxisChoice> from_cap;
  for (const auto& [a, along_face] : hypotheses) {
    AxisChoice c;
    c.axis = a;
    for (const DetectedPlane* f : faces) {
      const double along = std::abs(f->plane.normal.dot(a));
      if (along < sin_perp) c.sides.push_back(f);
      else if (along > cos_parallel) c.caps.push_back(f);
      else continue;
      c.points += f->inliers.size();
    }
    if (c.sides.size() >= 3) {
      if ((!best || c.points > best->points) && caps_at_ends(in, c)) best = std::move(c);
    } else if (along_face && !c.sides.empty() && caps_at_ends(in, c)) {
      from_cap.push_back(std::move(c));
    }
  }
  std::stable_sort(from_cap.begin(), from_cap.end(),
                   [](const AxisChoice& a, const AxisChoice& b) { return a.points > b.points; });
  std::vector<AxisChoice> out;
  if (best) out.push_back(std::move(*best));
  out.insert(out.end(), std::make_move_iterator(from_cap.begin()), std::make_move_iterator(from_cap.end()));
  return out;
}

// The side face's stretches in the cross-section: its points split where they leave a gap (two
// coplanar sides of a non-convex outline, such as a plus sign's arms, share one plane). The
// outward side is where the caps' points are not; without a cap the plane's own normal (away
// from the cloud's centroid) stands, which is right for every convex outline.
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

// Orders the runs around the outline: from the largest, each run's end goes on to the nearest
// start of a run not yet taken, until that is the first run's again. Runs off the walk (planes
// noise cuts from the edges between sides) are left out; only a closed walk, every corner
// closer than the gap allowed, is an outline.
std::optional<std::vector<SideRun>> chain_runs(std::vector<SideRun> runs, double max_gap) {
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

// Consecutive runs along one line (a side RANSAC cut in two) become one side.
// A side only a cap's border shows is placed less exactly: `loose_band` for it.
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

double turn_degrees(const geometry::Polygon2& p, std::size_t i) {
  const std::size_t n = p.size();
  const Eigen::Vector2d a = p[i] - p[(i + n - 1) % n], b = p[(i + 1) % n] - p[i];
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)) * 180.0 / kPi;
}

// A rectangle is a box's and a regular pentagon a pentagonal prism's: those keep their names.
bool equal_sides_and_turns(const geometry::Polygon2& p, double tolerance, double degrees) {
  const double mean = geometry::perimeter(p) / static_cast<double>(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (std::abs((p[(i + 1) % p.size()] - p[i]).norm() - mean) > tolerance * mean) return false;
    if (std::abs(turn_degrees(p, i) - 360.0 / static_cast<double>(p.size())) > degrees) return false;
  }
  return true;
}

bool is_rectangle(const geometry::Polygon2& p, double degrees) {
  if (p.size() != 4) return false;
  for (std::size_t i = 0; i < 4; ++i)
    if (std::abs(turn_degrees(p, i) - 90.0) > degrees) return false;
  return true;
}

// Total least-squares line through points, as a side: normal turned to `outward`.
std::optional<SideRun> fit_line(const std::vector<Eigen::Vector2d>& pts, const Eigen::Vector2d& outward) {
  if (pts.size() < 5) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p / static_cast<double>(pts.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : pts) cov.noalias() += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(cov);
  SideRun r;
  r.n = solver.eigenvectors().col(0).normalized();
  if (r.n.dot(outward) < 0) r.n = -r.n;
  r.d = r.n.dot(mean);
  r.weight = static_cast<double>(pts.size());
  return r;
}

// Root-mean-square distance of points from a side's line.
double rms_off_line(const std::vector<Eigen::Vector2d>& pts, const SideRun& r) {
  double sum = 0.0;
  for (const auto& p : pts) sum += (p.dot(r.n) - r.d) * (p.dot(r.n) - r.d);
  return std::sqrt(sum / static_cast<double>(std::max<std::size_t>(1, pts.size())));
}

// The traced outline bends where the cap's border is ragged, cutting one hidden side into
// several: two neighbouring sides no face shows whose border points lie on one line, within
// max_rms (about the grid's own rounding) in the root mean square, are one side. The closest
// such pair joins first, until none is left.
std::vector<SideRun> merge_unseen_runs(std::vector<SideRun> ring, double max_rms) {
  while (ring.size() > 3) {
    std::size_t best = ring.size();
    double best_rms = max_rms;
    std::optional<SideRun> joined;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const std::size_t j = (i + 1) % ring.size();
      if (ring[i].seen || ring[j].seen || ring[i].weight <= 0.0 || ring[j].weight <= 0.0) continue;
      std::vector<Eigen::Vector2d> pts = ring[i].border;
      pts.insert(pts.end(), ring[j].border.begin(), ring[j].border.end());
      auto line = fit_line(pts, ring[i].n + ring[j].n);
      if (!line) continue;
      const double rms = rms_off_line(pts, *line);
      if (!(rms <= best_rms)) continue;
      line->seen = false;
      line->t_lo = ring[i].start().dot(line->tangent());
      line->t_hi = ring[j].end().dot(line->tangent());
      line->border = std::move(pts);
      best = i, best_rms = rms, joined = std::move(line);
    }
    if (best == ring.size()) break;
    const std::size_t j = (best + 1) % ring.size();
    ring[best] = std::move(*joined);
    ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(j));
  }
  return ring;
}

// The outline from a cap (a single view shows one whole: nothing of a right prism stands above
// its cap): the cap's traced outline gives the corners roughly, and each side its line, from
// the side face seen along it, else from the cap's border points along it.
std::optional<std::vector<SideRun>> ring_from_cap(const SolveInput& in, const DetectedPlane& cap,
                                                  const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                                  const std::vector<SideRun>& runs, std::size_t& matched) {
  std::vector<Eigen::Vector2d> pts, border;
  for (std::uint32_t i : cap.inliers) pts.emplace_back(in.cloud[i].dot(u), in.cloud[i].dot(v));
  for (std::uint32_t i : cap.boundary) border.emplace_back(in.cloud[i].dot(u), in.cloud[i].dot(v));
  const double cell = in.cfg.prism_outline_cell * in.resolution;
  const geometry::Polygon2 rough = detail::face_outline_polygon(pts, cell, 1.5 * cell);
  if (rough.size() < 3) return std::nullopt;
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * kPi / 180.0);
  std::vector<SideRun> ring;
  matched = 0;
  for (std::size_t k = 0; k < rough.size(); ++k) {
    const Eigen::Vector2d a = rough[k], b = rough[(k + 1) % rough.size()];
    const Eigen::Vector2d dir = (b - a).normalized();
    const Eigen::Vector2d outward(dir.y(), -dir.x());
    const double len = (b - a).norm();
    const SideRun* best = nullptr;
    for (const SideRun& r : runs) {
      if (r.n.dot(outward) < cos_parallel || std::abs(r.d - r.n.dot(0.5 * (a + b))) > 2.0 * cell) continue;
      // Coplanar sides share a line: the run must lie along this edge, not another on it.
      const double ta = a.dot(r.tangent()), tb = b.dot(r.tangent());
      if (std::min(r.t_hi, std::max(ta, tb)) - std::max(r.t_lo, std::min(ta, tb)) < 0.5 * len) continue;
      if (!best || r.weight > best->weight) best = &r;
    }
    if (best) {
      ring.push_back(*best);
      ++matched;
      continue;
    }
    std::vector<Eigen::Vector2d> near;
    for (const auto& p : border) {
      const double t = (p - a).dot(dir);
      if (t < 0.15 * len || t > 0.85 * len) continue;
      if (std::abs((p - a).dot(outward)) <= 1.5 * cell) near.push_back(p);
    }
    auto line = fit_line(near, outward);
    if (!line) {
      SideRun r;
      r.n = outward;
      r.d = outward.dot(a);
      line = r;
    }
    line->border = std::move(near);
    line->seen = false;
    line->t_lo = a.dot(line->tangent());
    line->t_hi = b.dot(line->tangent());
    ring.push_back(*line);
  }
  // The grid rounds corners into short edges of their own: a side no face shows that is shorter
  // than a few cells between its neighbours, or that no border points line while its neighbours
  // meet within its length of it (the traced outline's chord across a rounded corner; a plus
  // sign's arm ends between parallel sides), is such a cut, and its neighbours meet instead.
  for (bool cut = true; cut && ring.size() > 3;) {
    cut = false;
    std::size_t shortest = ring.size();
    double shortest_len = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < ring.size(); ++k) {
      if (ring[k].seen) continue;
      const SideRun& prev = ring[(k + ring.size() - 1) % ring.size()];
      const SideRun& next = ring[(k + 1) % ring.size()];
      const auto a = intersect(prev, ring[k]);
      const auto b = intersect(ring[k], next);
      const double len = a && b ? (*b - *a).norm() : 0.0;
      if (!(len < in.cfg.prism_corner_cut_cells * cell)) {
        if (ring[k].weight > 0.0 || !a || !b) continue;
        const auto meet = intersect(prev, next);
        if (!meet || (*meet - 0.5 * (*a + *b)).norm() > len) continue;
      }
      if (len < shortest_len) shortest = k, shortest_len = len;
    }
    if (shortest < ring.size()) {
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(shortest));
      cut = true;
    }
  }
  return merge_unseen_runs(std::move(ring), in.cfg.prism_merge_rms_cells * cell);
}

// The prism along one axis hypothesis, or nothing when its outline or faces are no prism's.
std::optional<FittedSolid> fit_prism_along(const SolveInput& in, const AxisChoice& choice) {
  const Eigen::Vector3d axis = detail::extrusion_axis(choice.sides, choice.caps, choice.axis);
  const Eigen::Matrix3d frame = detail::frame_from_axis(axis);
  const Eigen::Vector3d u = frame.row(1).transpose(), v = frame.row(2).transpose();

  std::vector<Eigen::Vector2d> cap_points;
  for (const DetectedPlane* f : choice.caps)
    for (std::uint32_t i : f->inliers) cap_points.emplace_back(in.cloud[i].dot(u), in.cloud[i].dot(v));
  std::vector<SideRun> runs;
  for (const DetectedPlane* f : choice.sides)
    for (const SideRun& r : side_runs(in, *f, u, v, cap_points, choice.caps)) runs.push_back(r);
  // Every side seen: the sides' own stretches, ordered around. Else a cap's outline, with the
  // sides seen where they are (a single view); at least one side besides the cap.
  auto chained = chain_runs(runs, in.cfg.prism_corner_gap * in.resolution);
  bool from_cap = false;
  if (!chained && !choice.caps.empty()) {
    std::size_t matched = 0;
    chained = ring_from_cap(in, *choice.caps.front(), u, v, runs, matched);
    if (matched == 0) return std::nullopt;
    from_cap = true;
  }
  if (!chained) return std::nullopt;
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * kPi / 180.0);
  const double band = in.cfg.inlier_distance * in.resolution;
  const std::vector<SideRun> ring =
      merge_collinear(*chained, cos_parallel, band, std::max(band, 1.5 * in.cfg.prism_outline_cell * in.resolution));

  geometry::Polygon2 polygon;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto corner = intersect(ring[i], ring[(i + 1) % ring.size()]);
    if (!corner) return std::nullopt;
    polygon.push_back(*corner);
  }
  // Corner k joins side k and side k+1: the polygon's edge k+1 runs from corner k to k+1.
  if (polygon.size() < 3 || !(geometry::signed_area(polygon) > 0.0) || !geometry::is_simple(polygon))
    return std::nullopt;
  // A cap's border is ragged and notched where something hid it: a concave corner between two
  // sides only that border shows is no evidence of the cross-section.
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const double turn = turn_degrees(polygon, i);
    if (std::abs(turn) < in.cfg.prism_min_turn_degrees) return std::nullopt;
    if (turn < 0.0 && !ring[i].seen && !ring[(i + 1) % ring.size()].seen) return std::nullopt;
  }
  if (is_rectangle(polygon, in.cfg.parallel_degrees)) return std::nullopt;
  // A regular pentagon is the pentagonal prism's. Sides only a cap's border shows are placed less
  // exactly (as in merge_collinear): with one of them, regular within prism_guessed_slack times the
  // tolerances is.
  const bool guessed = std::any_of(ring.begin(), ring.end(), [](const SideRun& r) { return !r.seen; });
  const double slack = guessed ? in.cfg.prism_guessed_slack : 1.0;
  if (polygon.size() == 5 &&
      equal_sides_and_turns(polygon, slack * in.cfg.regular_tolerance, slack * in.cfg.parallel_degrees))
    return std::nullopt;
  const bool regular = equal_sides_and_turns(polygon, in.cfg.regular_tolerance, in.cfg.parallel_degrees);

  // Every side is seen across its width: a tangent strip of a curved surface is narrow.
  for (std::size_t i = 0; i < ring.size() && !from_cap; ++i) {
    const Eigen::Vector2d& from = polygon[(i + ring.size() - 1) % ring.size()];
    const Eigen::Vector2d& to = polygon[i];
    const double span = ring[i].t_hi - ring[i].t_lo;
    if (span + 2.0 * band < in.cfg.min_side_span * (to - from).norm()) return std::nullopt;
  }
  // The sides must account for the planes around the axis, and sides and caps for the points.
  std::vector<Eigen::Vector3d> side_normals;
  for (const SideRun& r : ring) side_normals.push_back(r.n.x() * u + r.n.y() * v);
  const auto on_sides = detail::points_on_planes_along(in.planes, side_normals, in.cfg.parallel_degrees);
  const auto on_caps = detail::points_on_planes_along(in.planes, {axis, -axis}, in.cfg.parallel_degrees);
  const double sin_perp = std::sin(in.cfg.perpendicular_degrees * kPi / 180.0);
  std::size_t around = 0;
  for (const DetectedPlane& p : in.planes.planes)
    if (std::abs(p.plane.normal.dot(axis)) < sin_perp) around += p.inliers.size();
  if (static_cast<double>(on_sides + on_caps) < in.cfg.polyhedron_face_share * static_cast<double>(in.cloud.size()) ||
      static_cast<double>(on_sides) < in.cfg.polyhedron_face_share * static_cast<double>(around))
    return std::nullopt;

  // Height: the caps where seen, else where the points end along the axis.
  auto [lo, hi] = detail::extrusion_extent(in, choice.caps, axis);
  const double height = hi - lo;
  if (!(height > 0.0)) return std::nullopt;

  // A prism's sides are rectangles the height of the prism: an octahedron's or a pyramid's
  // triangles, lined up around some axis, fill half of theirs.
  for (const SideRun& r : ring)
    if (r.seen && r.hull_area < in.cfg.prism_side_fill * (r.t_hi - r.t_lo) * height) return std::nullopt;

  const Eigen::Vector2d centroid = geometry::area_centroid(polygon);
  for (auto& p : polygon) p -= centroid;
  FittedSolid out;
  out.shape = Shape::prism;
  out.dimensions = {{"height", height}, {"sides", static_cast<double>(polygon.size())}};
  if (regular) out.dimensions.emplace_back("side", geometry::perimeter(polygon) / static_cast<double>(polygon.size()));
  out.center = centroid.x() * u + centroid.y() * v + 0.5 * (lo + hi) * axis;
  out.axes.row(0) = axis.transpose();
  out.axes.row(1) = u.transpose();
  out.axes.row(2) = v.transpose();
  out.polygon = polygon;
  // A non-convex outline's centroid may lie outside it (an L's): the interior point, from which
  // every direction meets the surface, is then the middle of the polygon's first ear.
  if (geometry::signed_distance(polygon, Eigen::Vector2d::Zero()) > 0.0) {
    const auto ears = geometry::triangulate(polygon);
    if (!ears.empty()) {
      const Eigen::Vector2d m = (polygon[ears[0][0]] + polygon[ears[0][1]] + polygon[ears[0][2]]) / 3.0;
      out.interior = out.center + m.x() * u + m.y() * v;
    }
  }
  const Point c = out.center;
  out.signed_distance = [c, axis, u, v, polygon, height](const Point& p) {
    const Eigen::Vector3d d = p - c;
    return std::max(std::abs(d.dot(axis)) - 0.5 * height,
                    geometry::signed_distance(polygon, Eigen::Vector2d(d.dot(u), d.dot(v))));
  };
  return out;
}

}  // namespace

std::optional<FittedSolid> fit_prism(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  for (const AxisChoice& choice : choose_axes(in, faces))
    if (auto solid = fit_prism_along(in, choice)) return solid;
  return std::nullopt;
}

}  // namespace cloudshape::pipeline
