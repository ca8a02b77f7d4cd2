// What solve_object measures of a fitted solid against the points: the share it explains, the
// share the points' own plane explains, how much of it a view covers, its flat faces, its kind.
#include "pipeline/solid_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_set>

#include "geometry/circle.hpp"
#include "geometry/convex_hull.hpp"
#include "geometry/pca.hpp"
#include "geometry/polygon.hpp"

namespace cloudshape::pipeline::detail {
namespace {

// Every step-th point of `size`, about `max_samples` of them (all when fewer).
std::size_t sample_step(std::size_t size, std::size_t max_samples) {
  return std::max<std::size_t>(1, size / std::max<std::size_t>(1, max_samples));
}

// Share of the face's convex hull its points cover, in cells of `cell`: a face is filled, while a
// single scan line is flat too (every lidar ring on a sphere lies in a plane) but covers a curve.
double hull_fill(const PointList& cloud, const DetectedPlane& face, double cell) {
  if (face.inliers.size() < 3 || !(cell > 0.0)) return 1.0;
  const Eigen::Vector3d n = face.plane.normal.normalized();
  const Eigen::Vector3d u = n.unitOrthogonal();
  const Eigen::Vector3d v = n.cross(u);
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(face.inliers.size());
  std::unordered_set<std::uint64_t> cells;
  for (std::uint32_t i : face.inliers) {
    const Eigen::Vector2d q(cloud[i].dot(u), cloud[i].dot(v));
    flat.push_back(q);
    const auto cx = static_cast<std::int64_t>(std::floor(q.x() / cell));
    const auto cy = static_cast<std::int64_t>(std::floor(q.y() / cell));
    cells.insert((static_cast<std::uint64_t>(cx) << 32) ^
                 static_cast<std::uint64_t>(cy & 0xFFFFFFFF));
  }
  const double area = std::abs(geometry::signed_area(geometry::convex_hull_2d(std::move(flat))));
  if (!(area > 0.0)) return 0.0;
  return std::min(1.0, static_cast<double>(cells.size()) * cell * cell / area);
}

// Whether a plane's points trace one circular arc in it, bowing well beyond their scatter about it
// (a lidar's scan ring on a sphere or a can): a curve, whatever share of its thin hull its cells
// cover. The scatter at most `max_scatter`, the arc's sagitta over its chord at least
// `min_sagitta`.
bool traces_an_arc(const PointList& cloud, const DetectedPlane& face, double max_scatter,
                   double min_sagitta) {
  if (face.inliers.size() < 5 || !(min_sagitta > 0.0)) return false;
  const Eigen::Vector3d n = face.plane.normal.normalized();
  const Point origin = cloud[face.inliers.front()];
  const auto circle = geometry::fit_circle_in_plane(cloud, face.inliers, origin, n);
  if (!circle || !(circle->radius > 0.0) || !std::isfinite(circle->radius)) return false;
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  const Eigen::Vector2d c(circle->center.dot(u), circle->center.dot(v));
  double sum_sq = 0.0;
  std::vector<double> angle;  // each point's about the centre, in the plane
  angle.reserve(face.inliers.size());
  for (std::uint32_t i : face.inliers) {
    const Eigen::Vector3d d = cloud[i] - circle->center;
    const double off = (d - d.dot(n) * n).norm() - circle->radius;
    sum_sq += off * off;
    angle.push_back(std::atan2(cloud[i].dot(v) - c.y(), cloud[i].dot(u) - c.x()));
  }
  if (std::sqrt(sum_sq / static_cast<double>(face.inliers.size())) > max_scatter) return false;
  // The arc's span: the circle less the widest gap between the points' angles about its centre.
  constexpr double kTwoPi = 6.283185307179586;
  const double span = kTwoPi - geometry::widest_angular_gap(angle), r = circle->radius;
  // Over half a turn the arc bows its whole radius off the chord across its widest part.
  const double sagitta = span >= 0.5 * kTwoPi ? r : r * (1.0 - std::cos(0.5 * span));
  return sagitta >= min_sagitta;
}

// A named dimension of a fitted solid (0 where it has none).
double dimension(const FittedSolid& s, const std::string& name) {
  for (const auto& [key, value] : s.dimensions)
    if (key == name) return value;
  return 0.0;
}

}  // namespace

Verification verify(const PointList& cloud, const FittedSolid& solid, double tolerance,
                    std::size_t max_samples) {
  Verification v;
  if (cloud.empty()) return v;
  const std::size_t step = sample_step(cloud.size(), max_samples);
  std::size_t n = 0, inside = 0;
  double sum = 0.0;
  for (std::size_t i = 0; i < cloud.size(); i += step, ++n) {
    const double d = std::abs(solid.signed_distance(cloud[i]));
    if (d <= tolerance) ++inside;
    sum += std::min(d, tolerance) * std::min(d, tolerance);
  }
  v.explained = static_cast<double>(inside) / static_cast<double>(n);
  v.rms = std::sqrt(sum / static_cast<double>(n));
  return v;
}

double plane_share(const PointList& cloud, double tolerance, std::size_t max_samples) {
  if (cloud.size() < 3) return 0.0;
  const std::size_t step = sample_step(cloud.size(), max_samples);
  std::vector<std::uint32_t> sample, inliers;
  for (std::size_t i = 0; i < cloud.size(); i += step)
    sample.push_back(static_cast<std::uint32_t>(i));
  inliers = sample;
  for (int fit = 0; fit < 3; ++fit) {
    if (inliers.size() < 3) return 0.0;
    const geometry::Pca pca = geometry::compute_pca(cloud, inliers);
    const Eigen::Vector3d normal = pca.eigenvectors.col(0);
    inliers.clear();
    for (std::uint32_t i : sample)
      if (std::abs(normal.dot(cloud[i] - pca.centroid)) <= tolerance) inliers.push_back(i);
  }
  return static_cast<double>(inliers.size()) / static_cast<double>(sample.size());
}

double rim_reach(const PointList& cloud, const FittedSolid& solid, double tolerance,
                 std::size_t max_samples) {
  if ((solid.shape != Shape::cone && solid.shape != Shape::frustum) || cloud.empty()) return 0.0;
  double radius = dimension(solid, "radius");
  if (solid.shape == Shape::frustum) radius = std::max(radius, dimension(solid, "top_radius"));
  if (!(radius > 0.0)) return 0.0;
  const Eigen::Vector3d axis = solid.axes.row(0).transpose();
  const std::size_t step = sample_step(cloud.size(), max_samples);
  double reach = 0.0;
  for (std::size_t i = 0; i < cloud.size(); i += step) {
    if (!(std::abs(solid.signed_distance(cloud[i])) <= tolerance)) continue;
    const Eigen::Vector3d d = cloud[i] - solid.center;
    reach = std::max(reach, (d - d.dot(axis) * axis).norm());
  }
  return reach / radius;
}

double cylinder_side_share(const PointList& cloud, const FittedSolid& solid, double tolerance,
                           std::size_t max_samples) {
  if (solid.shape != Shape::cylinder || cloud.empty()) return 0.0;
  const double radius = dimension(solid, "radius"), height = dimension(solid, "height");
  const Eigen::Vector3d axis = solid.axes.row(0).transpose();
  const std::size_t step = sample_step(cloud.size(), max_samples);
  std::size_t on_side = 0, seen = 0;
  for (std::size_t i = 0; i < cloud.size(); i += step, ++seen) {
    const Eigen::Vector3d d = cloud[i] - solid.center;
    const double along = d.dot(axis);
    if (std::abs(along) < 0.5 * height - tolerance &&
        std::abs((d - along * axis).norm() - radius) <= tolerance)
      ++on_side;
  }
  return static_cast<double>(on_side) / static_cast<double>(seen);
}

double off_surface_share(const PointList& cloud, const geometry::KdTree& tree,
                         const FittedSolid& solid, double far, double tolerance,
                         std::size_t max_samples) {
  if (cloud.size() < 2) return 0.0;
  // A point's 8 nearest neighbours ring it on a surface; three quarters of them inside too make
  // it part of a stretch of surface, where independent noise puts each neighbour inside beyond
  // the tolerance with the small chance the unexplained share gives (6 of 8 of 0.2: 0.1%).
  constexpr std::size_t kNeighbours = 8;
  const std::size_t step = sample_step(cloud.size(), max_samples);
  std::vector<std::uint32_t> near;
  std::vector<double> sq;
  std::size_t n = 0, inside = 0;
  for (std::size_t i = 0; i < cloud.size(); i += step, ++n) {
    if (solid.signed_distance(cloud[i]) >= -far) continue;
    tree.knn(cloud[i], kNeighbours + 1, near, &sq);
    // A point on a surface has a neighbour within the tolerance (two point spacings); strays
    // scattered through the solid's inside are each other's nearest, but farther apart.
    std::size_t also_inside = 0, close = 0;
    for (std::size_t k = 0; k < near.size(); ++k) {
      if (near[k] == i) continue;
      also_inside += solid.signed_distance(cloud[near[k]]) < -tolerance ? 1 : 0;
      close += sq[k] <= tolerance * tolerance ? 1 : 0;
    }
    if (close > 0 && 4 * also_inside >= 3 * kNeighbours) ++inside;
  }
  return static_cast<double>(inside) / static_cast<double>(n);
}

double sector_coverage(const PointList& cloud, const Point& center, const Eigen::Matrix3d& axes,
                       double min_share) {
  std::array<std::size_t, 27> count{};
  for (const Point& p : cloud) {
    const Eigen::Vector3d local = axes * (p - center);
    const double n = local.cwiseAbs().maxCoeff();
    if (!(n > 0.0)) continue;
    int idx = 0;
    for (int k = 0; k < 3; ++k) {
      const double c = local[k] / n;  // in [-1, 1]; the middle third is "no tilt" on this axis
      idx = idx * 3 + (c > 0.4142 ? 2 : c < -0.4142 ? 0 : 1);
    }
    ++count[idx];
  }
  const double floor = std::max(1.0, min_share * static_cast<double>(cloud.size()) / 26.0);
  int seen = 0;
  for (int i = 0; i < 27; ++i)
    if (i != 13 && static_cast<double>(count[i]) >= floor) ++seen;
  return seen / 26.0;
}

double flat_side_share(const FittedSolid& s, const PlaneSegmentation& planes,
                       const PointList& cloud, double cos_parallel, double cell, double min_fill,
                       double large_share, double arc_scatter, double arc_sagitta,
                       std::vector<double>& fills) {
  const std::size_t points = cloud.size();
  const bool tapered = s.shape == Shape::cone || s.shape == Shape::frustum;
  const bool revolution = s.shape == Shape::cylinder || tapered;
  if (!revolution && s.shape != Shape::sphere) return 0.0;
  const Eigen::Vector3d axis = s.axes.row(0).transpose();
  std::size_t flat = 0, large = 0, caps = 0;
  for (std::size_t k = 0; k < planes.planes.size(); ++k) {
    const DetectedPlane& p = planes.planes[k];
    if (!p.is_face) continue;
    if (revolution && std::abs(p.plane.normal.dot(axis)) >= cos_parallel) {
      caps += p.inliers.size();
      continue;
    }
    // The arc test only where the fill alone would count the plane flat: it costs a circle fit.
    if (std::isnan(fills[k])) {
      fills[k] = hull_fill(cloud, p, cell);
      if (fills[k] >= min_fill && traces_an_arc(cloud, p, arc_scatter * cell, arc_sagitta * cell))
        fills[k] = -1.0;
    }
    if (fills[k] < min_fill) continue;
    flat += p.inliers.size();
    if (static_cast<double>(p.inliers.size()) >= large_share * static_cast<double>(points))
      large += p.inliers.size();
  }
  if (2 * (points - std::min(points, caps)) < points) return 0.0;
  return static_cast<double>(tapered ? large : flat) / static_cast<double>(points - caps);
}

bool same_kind(const FittedSolid& a, const FittedSolid& b, double tolerance, double lean_degrees) {
  if (!same_family(a.shape, b.shape)) return false;
  const double max_lean = std::tan(lean_degrees * 3.14159265358979323846 / 180.0);
  const auto tapers = [&](const FittedSolid& f) {
    const double narrowing = dimension(f, "radius") - dimension(f, "top_radius");
    return f.shape == Shape::frustum && narrowing > 2.0 * tolerance &&
           narrowing > max_lean * dimension(f, "height");
  };
  const bool cylinder_and_frustum = (a.shape == Shape::cylinder && b.shape == Shape::frustum) ||
                                    (a.shape == Shape::frustum && b.shape == Shape::cylinder);
  return !(cylinder_and_frustum && (tapers(a) || tapers(b)));
}

}  // namespace cloudshape::pipeline::detail
