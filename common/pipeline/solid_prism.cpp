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
#include "pipeline/outline_fit.hpp"
#include "pipeline/prism_outline.hpp"
#include "pipeline/prism_side_runs.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

using detail::chain_runs;
using detail::intersect;
using detail::merge_collinear;
using detail::side_runs;
using detail::SideRun;

constexpr double kPi = 3.14159265358979323846;

struct AxisChoice {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::vector<const DetectedPlane*> sides, caps;
  std::size_t points = 0;
  bool cap_reading = false;  // a face's normal with three sides or more, read from the cap's outline
};

// Noise splits a cap into parallel planes a little apart (within inlier_distance of each other):
// the pieces of caps[k]'s cap are the caps facing its way along `axis` whose positions (`at`,
// along `axis`) lie that near its own, itself included, in the order of `caps`.
std::vector<std::size_t> cap_pieces(const SolveInput& in, const std::vector<const DetectedPlane*>& caps,
                                    const std::vector<double>& at, std::size_t k, const Eigen::Vector3d& axis) {
  const double same_cap = in.cfg.inlier_distance * in.resolution;
  const bool up = caps[k]->plane.normal.dot(axis) > 0;
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < caps.size(); ++j)
    if ((caps[j]->plane.normal.dot(axis) > 0) == up && std::abs(at[j] - at[k]) <= same_cap) out.push_back(j);
  return out;
}

std::vector<double> cap_positions(const SolveInput& in, const std::vector<const DetectedPlane*>& caps,
                                  const Eigen::Vector3d& axis) {
  std::vector<double> at;
  for (const DetectedPlane* f : caps) at.push_back(detail::face_position(in.cloud, *f, axis));
  return at;
}

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
  // A cap's place is where all of its pieces' points are, not where the smallest piece is.
  const std::vector<double> at = cap_positions(in, c.caps, c.axis);
  for (std::size_t k = 0; k < c.caps.size(); ++k) {
    const bool up = c.caps[k]->plane.normal.dot(c.axis) > 0;
    double sum = 0.0, points = 0.0;
    for (std::size_t j : cap_pieces(in, c.caps, at, k, c.axis)) {
      sum += at[j] * static_cast<double>(c.caps[j]->inliers.size());
      points += static_cast<double>(c.caps[j]->inliers.size());
    }
    if (!(points > 0.0) || std::abs(sum / points - (up ? hi : lo)) > band) return false;
  }
  return true;
}

// Axis hypotheses: every face's normal (a cap) and every two faces' common perpendicular (two
// sides). Three sides give an outline of their own: the hypothesis whose sides and caps hold most
// points is tried first. With fewer sides only a cap can (its traced border, ring_from_cap), so
// each face's normal with a side follows, most points first (with three sides or more too: a
// side RANSAC cut into parallel strips closes no outline, and the cap's still does): a view of a
// cap and one side has two such readings (either face the cap), and the outline decides.
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
    if (!caps_at_ends(in, c)) continue;
    if (along_face && !c.sides.empty()) {
      from_cap.push_back(c);
      from_cap.back().cap_reading = c.sides.size() >= 3;
    }
    if (c.sides.size() >= 3 && (!best || c.points > best->points)) best = std::move(c);
  }
  std::stable_sort(from_cap.begin(), from_cap.end(),
                   [](const AxisChoice& a, const AxisChoice& b) { return a.points > b.points; });
  std::vector<AxisChoice> out;
  if (best) out.push_back(std::move(*best));
  for (AxisChoice& c : from_cap)
    if (!best || c.axis != out.front().axis) out.push_back(std::move(c));
  return out;
}

double turn_degrees(const geometry::Polygon2& p, std::size_t i) {
  const std::size_t n = p.size();
  const Eigen::Vector2d a = p[i] - p[(i + n - 1) % n], b = p[(i + 1) % n] - p[i];
  return std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)) * 180.0 / kPi;
}

// A rectangle is a box's and a regular pentagon a pentagonal prism's: those keep their names. A
// side's length may stray `tolerance` of the mean, or `length_slack` (where the points place the
// corners less exactly than that share).
bool equal_sides_and_turns(const geometry::Polygon2& p, double tolerance, double degrees,
                           double length_slack) {
  const double mean = geometry::perimeter(p) / static_cast<double>(p.size());
  const double slack = std::max(tolerance * mean, length_slack);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (std::abs((p[(i + 1) % p.size()] - p[i]).norm() - mean) > slack) return false;
    if (std::abs(turn_degrees(p, i) - 360.0 / static_cast<double>(p.size())) > degrees) return false;
  }
  return true;
}

// `degrees`: per corner i (between the sides ending and starting there) how far from 90 it may be.
bool is_rectangle(const geometry::Polygon2& p, const std::vector<double>& degrees) {
  if (p.size() != 4 || degrees.size() != 4) return false;
  for (std::size_t i = 0; i < 4; ++i)
    if (std::abs(turn_degrees(p, i) - 90.0) > degrees[i]) return false;
  return true;
}

// Which seen run lies along the outline's side from a to b with outward normal `outward`: parallel,
// within two cells of it, over at least half its length (coplanar sides share a line: the run
// must lie along this side, not another on it); the heaviest such, or none.
std::optional<std::size_t> run_along(const std::vector<SideRun>& runs, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                     const Eigen::Vector2d& outward, double cos_parallel, double cell) {
  const double len = (b - a).norm();
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SideRun& r = runs[i];
    if (r.n.dot(outward) < cos_parallel || std::abs(r.d - r.n.dot(0.5 * (a + b))) > 2.0 * cell) continue;
    const double ta = a.dot(r.tangent()), tb = b.dot(r.tangent());
    if (std::min(r.t_hi, std::max(ta, tb)) - std::max(r.t_lo, std::min(ta, tb)) < 0.5 * len) continue;
    if (!best || r.weight > runs[*best].weight) best = i;
  }
  return best;
}

// A cap's outline as its own points and border give it, before any side seen is matched: the
// same for every axis hypothesis that projects the same cap the same way, so each is fitted once
// per solid (the axis hypotheses of a box's view often share a cap and its frame).
struct CapOutline {
  std::vector<Eigen::Vector2d> points, border;  // the cap's projections: the key
  std::vector<detail::OutlineSide> sides;       // fit_outline_sides of its traced outline; < 3: none
};
using CapOutlines = std::vector<CapOutline>;

// The outline from a cap (a single view shows one whole: nothing of a right prism stands above
// its cap): the cap's traced outline gives the sides roughly; their lines are refitted to the
// cap's border and the bends its raggedness makes are joined (fit_outline_sides), then each side
// a face is seen along takes that face's line and the rest are fitted again around them.
std::optional<std::vector<SideRun>> ring_from_cap(const SolveInput& in, const DetectedPlane& cap,
                                                  const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                                  const std::vector<SideRun>& runs, std::size_t& matched,
                                                  CapOutlines& outlines) {
  std::vector<Eigen::Vector2d> pts, border;
  for (std::uint32_t i : cap.inliers) pts.emplace_back(in.cloud[i].dot(u), in.cloud[i].dot(v));
  for (std::uint32_t i : cap.boundary) border.emplace_back(in.cloud[i].dot(u), in.cloud[i].dot(v));
  const double cell = in.cfg.prism_outline_cell * in.resolution;
  matched = 0;
  detail::OutlineFitParameters fit;
  fit.cell = cell;
  fit.band_cells = in.cfg.prism_border_band_cells;
  fit.min_length_cells = in.cfg.prism_corner_cut_cells;
  fit.join_evidence = in.cfg.prism_join_evidence;
  std::size_t known = 0;
  while (known < outlines.size() && !(outlines[known].points == pts && outlines[known].border == border)) ++known;
  if (known == outlines.size()) {
    CapOutline fresh{pts, border, {}};
    const geometry::Polygon2 rough = detail::face_outline_polygon(pts, cell, 1.5 * cell);
    if (rough.size() >= 3) {
      for (std::size_t k = 0; k < rough.size(); ++k) {
        const Eigen::Vector2d a = rough[k], b = rough[(k + 1) % rough.size()];
        const Eigen::Vector2d dir = (b - a).normalized();
        detail::OutlineSide s;
        s.n = Eigen::Vector2d(dir.y(), -dir.x());
        s.d = s.n.dot(a);
        fresh.sides.push_back(std::move(s));
      }
      fresh.sides = detail::fit_outline_sides(std::move(fresh.sides), border, fit);
    }
    outlines.push_back(std::move(fresh));
  }
  if (outlines[known].sides.size() < 3) return std::nullopt;
  std::vector<detail::OutlineSide> sides = outlines[known].sides;

  const double cos_parallel = std::cos(in.cfg.parallel_degrees * kPi / 180.0);
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const Eigen::Vector2d& a = sides[(k + sides.size() - 1) % sides.size()].end;
    const auto run = run_along(runs, a, sides[k].end, sides[k].n, cos_parallel, cell);
    if (!run) continue;
    sides[k].n = runs[*run].n;
    sides[k].d = runs[*run].d;
    sides[k].fixed = true;
    sides[k].label = static_cast<int>(*run);
  }
  // One face seen along two neighbouring sides: they are one.
  for (std::size_t k = 0; sides.size() > 3 && k < sides.size();) {
    const std::size_t next = (k + 1) % sides.size();
    if (sides[k].fixed && sides[next].fixed && sides[k].label == sides[next].label) {
      sides[k].end = sides[next].end;
      sides.erase(sides.begin() + static_cast<std::ptrdiff_t>(next));
      if (next < k) --k;
    } else {
      ++k;
    }
  }
  // Between two faces seen whose points end near where their planes meet (chain_runs' test), a
  // side only the border shows is the grid's rounding of their corner.
  const double corner_gap = in.cfg.prism_corner_gap * in.resolution;
  for (std::size_t k = 0; sides.size() > 3 && k < sides.size();) {
    const std::size_t prev = (k + sides.size() - 1) % sides.size(), next = (k + 1) % sides.size();
    if (!sides[k].fixed && sides[prev].fixed && sides[next].fixed) {
      const SideRun& a = runs[static_cast<std::size_t>(sides[prev].label)];
      const SideRun& b = runs[static_cast<std::size_t>(sides[next].label)];
      const auto corner = intersect(a, b);
      if (corner && (a.end() - *corner).norm() <= corner_gap && (b.start() - *corner).norm() <= corner_gap) {
        sides[prev].end = *corner;
        sides.erase(sides.begin() + static_cast<std::ptrdiff_t>(k));
        continue;
      }
    }
    ++k;
  }
  for (const auto& s : sides) matched += s.fixed ? 1 : 0;
  if (matched == 0) return std::nullopt;
  sides = detail::fit_outline_sides(std::move(sides), border, fit);
  if (sides.size() < 3) return std::nullopt;

  std::vector<SideRun> ring;
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const detail::OutlineSide& s = sides[k];
    if (s.fixed) {
      ring.push_back(runs[static_cast<std::size_t>(s.label)]);
      continue;
    }
    SideRun r;
    r.n = s.n;
    r.d = s.d;
    r.seen = false;
    r.weight = static_cast<double>(s.points.size());
    r.t_lo = sides[(k + sides.size() - 1) % sides.size()].end.dot(r.tangent());
    r.t_hi = s.end.dot(r.tangent());
    ring.push_back(std::move(r));
  }
  return ring;
}

// The prism along one axis hypothesis, or nothing when its outline or faces are no prism's.
// `closed`: set when the sides' own stretches closed an outline.
std::optional<FittedSolid> fit_prism_along(const SolveInput& in, const AxisChoice& choice, bool& closed,
                                           CapOutlines& outlines) {
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
  closed = closed || chained.has_value();
  bool from_cap = false;
  if (!chained && !choice.caps.empty()) {
    std::size_t matched = 0;
    // The outline is traced on all of the cap's pieces (one piece alone is a sparse, notched copy
    // of the cap).
    DetectedPlane cap = *choice.caps.front();
    const std::vector<double> at = cap_positions(in, choice.caps, axis);
    for (std::size_t k : cap_pieces(in, choice.caps, at, 0, axis)) {
      if (k == 0) continue;
      const DetectedPlane& piece = *choice.caps[k];
      cap.inliers.insert(cap.inliers.end(), piece.inliers.begin(), piece.inliers.end());
      cap.boundary.insert(cap.boundary.end(), piece.boundary.begin(), piece.boundary.end());
    }
    chained = ring_from_cap(in, cap, u, v, runs, matched, outlines);
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
  // A cap's border is ragged and notched where something hid it: in a scene (a sensor's
  // viewpoint known, or other objects in the cloud) a neighbour may have, and a concave corner
  // between two sides only that border shows is no evidence of the cross-section. An object
  // alone in its cloud (SolveInput::alone) has nothing beside it: such a notch is
  // the cross-section's where it is deep (the notches take solve.prism_notch_min_share of the
  // outline's convex hull) and nothing of the object stands in it (a sparse stretch of the cap's
  // border has the solid's own sides beyond it: no more than solve.prism_notch_outside_share of
  // the points outside the outline by more than inlier_distance).
  bool border_notch = false;
  std::vector<char> concave_corner(polygon.size(), 0);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const double turn = turn_degrees(polygon, i);
    if (std::abs(turn) < in.cfg.prism_min_turn_degrees) return std::nullopt;
    concave_corner[i] = turn < 0.0;
    if (turn < 0.0 && !ring[i].seen && !ring[(i + 1) % ring.size()].seen) border_notch = true;
  }
  if (border_notch) {
    if (!in.alone) return std::nullopt;
    // A shallow notch is a dented border (a real box's rounded or crushed edge), not a notch.
    const double hull = std::abs(geometry::signed_area(geometry::convex_hull_2d(polygon)));
    if (!(hull - geometry::signed_area(polygon) >= in.cfg.prism_notch_min_share * hull)) return std::nullopt;
    std::size_t outside = 0;
    for (const Point& p : in.cloud)
      outside += geometry::signed_distance(polygon, Eigen::Vector2d(p.dot(u), p.dot(v))) > band;
    if (static_cast<double>(outside) > in.cfg.prism_notch_outside_share * static_cast<double>(in.cloud.size()))
      return std::nullopt;
  }
  // A rectangle is the box's, a regular pentagon the pentagonal prism's. Sides only a cap's border
  // shows are placed less exactly (as in merge_collinear): a corner on one of them is a right angle
  // within prism_guessed_slack times parallel_degrees (a real box's short side seen only as its
  // cap's ragged border is 10-12 degrees off), one between two seen faces within parallel_degrees
  // (a rhombus seen on two sides keeps its measured corner); with a guessed side a pentagon regular
  // within the slack times the tolerances is regular.
  const auto guessed_sides = static_cast<int>(
      std::count_if(ring.begin(), ring.end(), [](const SideRun& r) { return !r.seen; }));
  const double slack = guessed_sides > 0 ? in.cfg.prism_guessed_slack : 1.0;
  std::vector<double> right_angle_tolerance(ring.size(), in.cfg.parallel_degrees);
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (!ring[i].seen || !ring[(i + 1) % ring.size()].seen)
      right_angle_tolerance[i] *= in.cfg.prism_guessed_slack;
  if (is_rectangle(polygon, right_angle_tolerance)) return std::nullopt;
  // Each corner is placed within the verification's tolerance (inlier_distance resolutions): under
  // a depth camera's noise that is more than regular_tolerance of a small prism's side.
  const double corner_slack = in.cfg.inlier_distance * in.resolution;
  if (polygon.size() == 5 &&
      equal_sides_and_turns(polygon, slack * in.cfg.regular_tolerance,
                            slack * in.cfg.parallel_degrees, slack * corner_slack))
    return std::nullopt;
  const bool regular = equal_sides_and_turns(polygon, in.cfg.regular_tolerance,
                                             in.cfg.parallel_degrees, corner_slack);

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
  // triangles, lined up around some axis, fill half of theirs. A side at a concave corner (an L's
  // or a T's inner face) of an object alone in its cloud is seen in part where the prism's own arm
  // stands between it and the sensor, and nothing else could have cut the notch: only the other
  // sides are held to it there (lined-up triangles make a convex outline). In a scene a notch may
  // be where a neighbour hid the cap (as for border_notch above), and every side is held to it.
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const SideRun& r = ring[i];
    const bool at_notch = concave_corner[(i + ring.size() - 1) % ring.size()] || concave_corner[i];
    if (r.seen && !(in.alone && at_notch) &&
        r.hull_area < in.cfg.prism_side_fill * (r.t_hi - r.t_lo) * height)
      return std::nullopt;
  }

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
  out.guessed_sides = guessed_sides;
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
  // Where the sides around some axis closed an outline, they told the cross-section: a cap's
  // reading of three sides or more is only for sides that close none.
  bool closed = false;
  CapOutlines outlines;
  for (const AxisChoice& choice : choose_axes(in, faces)) {
    if (choice.cap_reading && closed) continue;
    if (auto solid = fit_prism_along(in, choice, closed, outlines)) return solid;
  }
  return std::nullopt;
}

}  // namespace cloudshape::pipeline
