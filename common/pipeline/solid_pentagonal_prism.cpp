// Regular pentagonal prism from the faces seen: two side faces meeting at 108 deg (normals
// 72 or 144 deg apart) fix its axis and the pentagon's turn; seen sides, and where their points
// end against hidden sides, fix the pentagon; caps or the points' ends the height.
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <tuple>
#include <utility>

#include "geometry/convex_hull.hpp"
#include "geometry/polygon.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSideStep = 2.0 * kPi / 5.0;  // 72 deg between neighbouring side normals

struct PrismFaces {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::vector<const DetectedPlane*> sides;
  std::vector<const DetectedPlane*> caps;
  std::size_t points = 0;
};

// Angle between two unit vectors as a multiple of 72 deg: 1 or 2 for two sides of a
// pentagonal prism, with `tolerance` radians of slack; 0 otherwise.
int side_steps(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tolerance) {
  const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  for (int k = 1; k <= 2; ++k)
    if (std::abs(angle - k * kSideStep) <= tolerance) return k;
  return 0;
}

// The faces around the axis that two faces at a side angle define, best pair by points:
// sides perpendicular to it at multiples of 72 deg from the pair, caps along it.
std::optional<PrismFaces> prism_faces(const std::vector<const DetectedPlane*>& faces,
                                      const config::SolveConfig& cfg) {
  const double tolerance = cfg.parallel_degrees * kPi / 180.0;
  const double sin_perp = std::sin(cfg.perpendicular_degrees * kPi / 180.0);
  const double cos_parallel = std::cos(cfg.parallel_degrees * kPi / 180.0);
  std::optional<PrismFaces> best;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      const Eigen::Vector3d& ni = faces[i]->plane.normal;
      if (side_steps(ni, faces[j]->plane.normal, tolerance) == 0) continue;
      PrismFaces set;
      set.axis = ni.cross(faces[j]->plane.normal).normalized();
      for (const DetectedPlane* f : faces) {
        const Eigen::Vector3d& n = f->plane.normal;
        const double along = std::abs(n.dot(set.axis));
        const bool side = along < sin_perp && (f == faces[i] || side_steps(ni, n, tolerance) > 0);
        if (side) set.sides.push_back(f);
        if (along > cos_parallel) set.caps.push_back(f);
        if (side || along > cos_parallel) set.points += f->inliers.size();
      }
      if (!best || set.points > best->points) best = set;
    }
  }
  return best;
}

// A face's points along `direction`: their 2nd and 98th percentiles (both 0 for fewer than two),
// the ends of a face seen whole less its stray points.
std::pair<double, double> face_range(const PointList& cloud, const DetectedPlane& face,
                                     const Eigen::Vector3d& direction) {
  std::vector<double> t;
  t.reserve(face.inliers.size());
  for (std::uint32_t i : face.inliers) t.push_back(cloud[i].dot(direction));
  if (t.size() < 2) return {0.0, 0.0};
  const auto at = [&t](double q) {
    const auto k = static_cast<std::size_t>(q * static_cast<double>(t.size() - 1));
    std::nth_element(t.begin(), t.begin() + k, t.end());
    return t[k];
  };
  const double lo = at(0.02);
  return {lo, at(0.98)};
}

// Width of a face's points along `across`, between their 2nd and 98th percentiles.
double side_span(const PointList& cloud, const DetectedPlane& face, const Eigen::Vector3d& across) {
  const auto [lo, hi] = face_range(cloud, face, across);
  return hi - lo;
}

// Where a seen side's points end along a hidden neighbour's normal `direction`: the edge the two
// sides share. Their 98th percentile, moved out by the 2% of their spread that evenly spread points
// leave beyond it. The side's own points, not all of the object's: those reaching farthest out are
// depth noise and a sensor's flying pixels at the silhouette, which placed a Kinect's hidden sides
// 3-17 mm out and the pentagon's side 7-30% too long.
double shared_edge(const PointList& cloud, const DetectedPlane& seen_side,
                   const Eigen::Vector3d& direction) {
  const auto [lo, hi] = face_range(cloud, seen_side, direction);
  return hi + (hi - lo) * 0.02 / 0.96;
}

// Share of its rectangle (its points' width across, by the prism's height) the convex hull of a
// side's points covers: a prism's side is a rectangle, a tetrahedron's or pyramid's face a
// triangle that fills half.
double side_fill(const PointList& cloud, const DetectedPlane& face, const Eigen::Vector3d& axis,
                 const Eigen::Vector3d& across, double height) {
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(face.inliers.size());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::uint32_t i : face.inliers) {
    flat.emplace_back(cloud[i].dot(axis), cloud[i].dot(across));
    lo = std::min(lo, flat.back().y()), hi = std::max(hi, flat.back().y());
  }
  const double rectangle = (hi - lo) * height;
  if (flat.size() < 3 || !(rectangle > 0.0)) return 0.0;
  return std::abs(geometry::signed_area(geometry::convex_hull_2d(std::move(flat)))) / rectangle;
}

// Share of the pentagon (apothem `apothem` about the axis through `on_axis`) that the convex hull
// of the points on a cap's plane, `at` along the axis, covers. All points within `band` of the
// plane count: noise splits one cap into several parallel planes, each holding only part of it.
double cap_fill(const SolveInput& in, const Point& on_axis, const Eigen::Vector3d& axis, const Eigen::Vector3d& u,
                const Eigen::Vector3d& v, double at, double apothem, double band) {
  std::vector<Eigen::Vector2d> on_cap;
  for (const Point& p : in.cloud) {
    const Eigen::Vector3d d = p - on_axis;
    if (std::abs(d.dot(axis) - at) <= band) on_cap.emplace_back(d.dot(u), d.dot(v));
  }
  const double pentagon = 5.0 * apothem * apothem * std::tan(kPi / 5.0);
  return std::abs(geometry::signed_area(geometry::convex_hull_2d(std::move(on_cap)))) / pentagon;
}

// Points of the planes (faces or not) whose normals are perpendicular to the axis.
std::size_t points_around(const PlaneSegmentation& planes, const Eigen::Vector3d& axis,
                          const config::SolveConfig& cfg) {
  const double sin_perp = std::sin(cfg.perpendicular_degrees * kPi / 180.0);
  std::size_t n = 0;
  for (const DetectedPlane& p : planes.planes)
    if (std::abs(p.plane.normal.dot(axis)) < sin_perp) n += p.inliers.size();
  return n;
}

}  // namespace

std::optional<FittedSolid> fit_pentagonal_prism(const SolveInput& in) {
  const auto found = prism_faces(detail::faces_by_size(in.planes), in.cfg);
  if (!found) return std::nullopt;
  const Eigen::Vector3d axis = detail::extrusion_axis(found->sides, found->caps, found->axis);
  const Eigen::Matrix3d frame = detail::frame_from_axis(axis);
  const Eigen::Vector3d u = frame.row(1).transpose(), v = frame.row(2).transpose();

  // The pentagon's turn: side normals are 72 deg apart, so 5 phi is the same for all.
  std::complex<double> orientation = 0.0;
  for (const DetectedPlane* f : found->sides) {
    const double phi = std::atan2(f->plane.normal.dot(v), f->plane.normal.dot(u));
    orientation += static_cast<double>(f->inliers.size()) * std::polar(1.0, 5.0 * phi);
  }
  const double phi0 = std::arg(orientation) / 5.0;
  std::array<Eigen::Vector3d, 5> normals;
  for (int k = 0; k < 5; ++k)
    normals[k] = std::cos(phi0 + k * kSideStep) * u + std::sin(phi0 + k * kSideStep) * v;
  // The prism must account for the points, and its sides for the planes around its axis:
  // tangent strips of a curved side lie around the axis at every angle, not at 72 deg steps.
  const std::vector<Eigen::Vector3d> side_normals(normals.begin(), normals.end());
  const auto on_sides = detail::points_on_planes_along(in.planes, side_normals, in.cfg.parallel_degrees);
  const auto on_caps = detail::points_on_planes_along(in.planes, {axis, -axis}, in.cfg.parallel_degrees);
  if (static_cast<double>(on_sides + on_caps) < in.cfg.polyhedron_face_share * static_cast<double>(in.cloud.size()) ||
      static_cast<double>(on_sides) < in.cfg.polyhedron_face_share * static_cast<double>(points_around(in.planes, axis, in.cfg)))
    return std::nullopt;

  // Where each side's plane lies along its normal: a seen side where its points are; a
  // hidden side next to a seen one where that side's points end, at their shared edge (the seen
  // side is whole up to it; between two seen sides, the mean of both ends). A side next to none
  // touches the points at most at a corner (or along a cap's edge, which a partly hidden cap does
  // not show): it stays free.
  std::array<double, 5> offset{}, weight{};
  std::array<bool, 5> seen{}, known{};
  std::array<const DetectedPlane*, 5> seen_face{};
  for (const DetectedPlane* f : found->sides) {
    const double phi = std::atan2(f->plane.normal.dot(v), f->plane.normal.dot(u));
    const int k = static_cast<int>(std::lround((phi - phi0) / kSideStep) % 5 + 5) % 5;
    if (seen[k]) continue;
    seen[k] = known[k] = true;
    seen_face[k] = f;
    offset[k] = detail::face_position(in.cloud, *f, normals[k]);
    weight[k] = std::sqrt(static_cast<double>(f->inliers.size()));
  }
  for (int k = 0; k < 5; ++k) {
    if (seen[k]) continue;
    double ends = 0.0;
    int neighbours = 0;
    for (int j : {(k + 1) % 5, (k + 4) % 5}) {
      if (!seen_face[j]) continue;
      ends += shared_edge(in.cloud, *seen_face[j], normals[k]);
      ++neighbours;
    }
    if (neighbours > 0) {
      known[k] = true;
      offset[k] = ends / neighbours;
      weight[k] = 1.0;
    }
  }
  // Every side sits at the apothem a from the axis: n_k.(o + s u + t v) = offset_k - a.
  // A seen side's position is the mean of many points, a hidden one's the end of a few:
  // rows weighted by the square root of the points behind them (their precision).
  const Point origin = found->sides.front()->plane.project(in.cloud[found->sides.front()->inliers.front()]);
  std::vector<int> rows;
  for (int k = 0; k < 5; ++k)
    if (known[k]) rows.push_back(k);
  if (rows.size() < 3) return std::nullopt;
  Eigen::MatrixXd m(rows.size(), 3);
  Eigen::VectorXd rhs(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Eigen::Vector3d& n = normals[rows[r]];
    const double w = weight[rows[r]];
    m(r, 0) = w * n.dot(u);
    m(r, 1) = w * n.dot(v);
    m(r, 2) = w;
    rhs(r) = w * (offset[rows[r]] - n.dot(origin));
  }
  const Eigen::Vector3d sol = m.colPivHouseholderQr().solve(rhs);
  const double apothem = sol(2);
  if (!(apothem > 0.0) || !sol.allFinite()) return std::nullopt;
  const Point on_axis = origin + sol(0) * u + sol(1) * v;

  // Whether a cap is seen at the end `up` (along the axis) or the other, however many planes
  // noise split it into.
  const auto cap_seen = [&](bool up) {
    return std::any_of(found->caps.begin(), found->caps.end(), [&](const DetectedPlane* c) {
      return (c->plane.normal.dot(axis) > 0) == up;
    });
  };
  // Height: a cap where one is seen, else where the seen sides' own points end along the axis (the
  // farthest of them: a side may be hidden in part), as for the hidden sides above: the points'
  // end there is a depth camera's noise and flying pixels, 10-17% beyond a Kinect's prisms.
  auto [lo, hi] = detail::extrusion_extent(in, found->caps, axis);
  const double points_height = hi - lo;
  for (const bool up : {true, false}) {
    if (cap_seen(up)) continue;
    const Eigen::Vector3d along = up ? axis : Eigen::Vector3d(-axis);
    double end = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < 5; ++k)
      if (seen_face[k]) end = std::max(end, shared_edge(in.cloud, *seen_face[k], along));
    if (!std::isfinite(end)) continue;
    (up ? hi : lo) = up ? end : -end;
  }
  lo -= on_axis.dot(axis);
  hi -= on_axis.dot(axis);
  const double height = hi - lo;
  if (!(height > 0.0)) return std::nullopt;
  // A seen side is seen whole, across its width: a strip of a curved surface is narrow.
  // Near each edge a side's plane may lose a band (the verification's tolerance) of its
  // points to the neighbouring side. Where its end placed a hidden neighbour, it is no wider
  // than the side and the bands its neighbours' points reach into across each edge (edge_band /
  // sin 72 deg) either: a box's two faces, their normals 78 deg apart in a noisy frame, passed
  // for two sides of a pentagonal prism whose side was 25% narrower than one of them. (Between
  // seen sides the sides' positions fix the pentagon, and under noise and outliers a whole prism's
  // sides span up to 19% more than the side.)
  const double side = 2.0 * apothem * std::tan(kPi / 5.0);
  const double edge_band = in.cfg.inlier_distance * in.resolution;
  for (int k = 0; k < 5; ++k) {
    if (!seen_face[k]) continue;
    const double span = side_span(in.cloud, *seen_face[k], axis.cross(normals[k]));
    const bool placed_hidden =
        (known[(k + 1) % 5] && !seen[(k + 1) % 5]) || (known[(k + 4) % 5] && !seen[(k + 4) % 5]);
    if (span + 2.0 * edge_band < in.cfg.min_side_span * side ||
        (placed_hidden && span > side + 2.0 * edge_band / std::sin(kSideStep)))
      return std::nullopt;
  }
  // And with no cap seen to fix the height, a rectangle as long as the points reach along the
  // axis: a tetrahedron's two faces meeting at 108 deg are triangles. (Under a cap a side is the
  // cap's edge extruded; an uneven cloud's thin patches there may cut its hull's corners.)
  for (int k = 0; k < 5 && found->caps.empty(); ++k)
    if (seen_face[k] && side_fill(in.cloud, *seen_face[k], axis, axis.cross(normals[k]),
                                  points_height) < in.cfg.prism_side_fill)
      return std::nullopt;

  // A cap seen is seen whole: nothing of a right prism stands above it. Two sides at a pentagon's
  // angle fit a rhombic prism as well; its cap, seen, shows four corners. Each end once, however
  // many planes noise split its cap into.
  for (const bool up : {true, false}) {
    if (cap_seen(up) && cap_fill(in, on_axis, axis, u, v, up ? hi : lo, apothem,
                                 in.cfg.inlier_distance * in.resolution) < in.cfg.cap_section_fill)
      return std::nullopt;
  }
  FittedSolid out;
  out.shape = Shape::pentagonal_prism;
  out.dimensions = {{"side", side}, {"height", height}};
  out.center = on_axis + 0.5 * (lo + hi) * axis;
  out.axes.row(0) = axis.transpose();
  out.axes.row(1) = normals[0].transpose();
  out.axes.row(2) = axis.cross(normals[0]).transpose();
  const Point c = out.center;
  out.signed_distance = [c, axis, normals, apothem, height](const Point& p) {
    const Eigen::Vector3d d = p - c;
    double sd = std::abs(d.dot(axis)) - 0.5 * height;
    for (const Eigen::Vector3d& n : normals) sd = std::max(sd, d.dot(n) - apothem);
    return sd;
  };
  return out;
}

}  // namespace cloudshape::pipeline
