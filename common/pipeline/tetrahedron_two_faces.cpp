#include "pipeline/tetrahedron_two_faces.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/convex_hull.hpp"
#include "geometry/polygon.hpp"

namespace cloudshape::pipeline::detail {

double face_hull_area(const PointList& cloud, const DetectedPlane& face) {
  Eigen::Vector3d u, v;
  geometry::plane_basis(face.plane.normal, u, v);
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(face.inliers.size());
  for (std::uint32_t i : face.inliers) flat.emplace_back(cloud[i].dot(u), cloud[i].dot(v));
  return std::abs(geometry::signed_area(geometry::convex_hull_2d(geometry::hull_candidates(flat))));
}

namespace {

// An edge's line is fitted along the middle of its guessed span, split into kBins stretches: its
// ends run into the corners, whose guesses are what is being corrected.
constexpr double kMiddleFrom = 0.15, kMiddleTo = 0.85;
constexpr int kBins = 16;

// Total least-squares line through 2-D points: a point on it and its unit direction.
std::optional<std::pair<Eigen::Vector2d, Eigen::Vector2d>> line_through(
    const std::vector<Eigen::Vector2d>& pts) {
  if (pts.size() < 5) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : pts) mean += p / static_cast<double>(pts.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& p : pts) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  return std::make_pair(mean, Eigen::Vector2d(eig.eigenvectors().col(1)));
}

std::optional<Eigen::Vector2d> meet(const std::pair<Eigen::Vector2d, Eigen::Vector2d>& a,
                                    const std::pair<Eigen::Vector2d, Eigen::Vector2d>& b) {
  Eigen::Matrix2d m;
  m << a.second, -b.second;
  if (std::abs(m.determinant()) < 1e-9) return std::nullopt;
  const Eigen::Vector2d t = m.inverse() * (b.first - a.first);
  return a.first + t(0) * a.second;
}

// The corners from lines, not from the farthest points: sampling leaves an acute corner's tip
// short by about a point spacing. Each face's two other edges are fitted to its outermost points
// along their middles; they meet each other at the face's third corner and the shared line at
// the shared edge's ends (the two faces' estimates averaged). A corner stays as it was where a
// line has too few points.
void refine_corners(const SolveInput& in, const DetectedPlane& a, const DetectedPlane& b,
                    const Point& on_line, const Eigen::Vector3d& along, Point& v0, Point& v1,
                    std::array<Point, 2>& apex) {
  std::array<double, 2> t_sum{0.0, 0.0};
  std::array<int, 2> t_count{0, 0};
  for (int k = 0; k < 2; ++k) {
    const DetectedPlane& f = k == 0 ? a : b;
    Eigen::Vector3d u, v;
    geometry::plane_basis(f.plane.normal, u, v);
    const auto flat = [&](const Point& p) { return Eigen::Vector2d(p.dot(u), p.dot(v)); };
    const Eigen::Vector2d c0 = flat(v0), c1 = flat(v1), top = flat(apex[k]);
    const std::array<std::pair<Eigen::Vector2d, Eigen::Vector2d>, 2> edges{std::pair{c0, top},
                                                                           std::pair{c1, top}};
    // Per edge, in each stretch of its middle, the face's point farthest out (away from the
    // opposite corner): the edge's trace, a sample's spacing at most inside it.
    std::array<std::vector<Eigen::Vector2d>, 2> near;
    for (int e = 0; e < 2; ++e) {
      const Eigen::Vector2d from = edges[e].first, d = edges[e].second - edges[e].first;
      const Eigen::Vector2d opposite = e == 0 ? c1 : c0;
      Eigen::Vector2d out(-d.y(), d.x());
      out.normalize();
      if (out.dot(opposite - from) > 0.0) out = -out;
      std::array<double, kBins> best;
      best.fill(-std::numeric_limits<double>::infinity());
      std::array<Eigen::Vector2d, kBins> at{};
      for (std::uint32_t i : f.inliers) {
        const Eigen::Vector2d p = flat(in.cloud[i]);
        const double t = (p - from).dot(d) / d.squaredNorm();
        if (t < kMiddleFrom || t >= kMiddleTo) continue;
        const auto bin =
            static_cast<std::size_t>((t - kMiddleFrom) / (kMiddleTo - kMiddleFrom) * kBins);
        const double o = (p - from).dot(out);
        if (o > best[bin]) best[bin] = o, at[bin] = p;
      }
      for (int k2 = 0; k2 < kBins; ++k2)
        if (std::isfinite(best[k2])) near[e].push_back(at[k2]);
    }
    const auto l0 = line_through(near[0]), l1 = line_through(near[1]);
    if (!l0 || !l1) continue;
    if (const auto corner = meet(*l0, *l1))
      apex[k] = f.plane.project((*corner)(0) * u + (*corner)(1) * v);
    const std::pair<Eigen::Vector2d, Eigen::Vector2d> shared{flat(on_line),
                                                             flat(on_line + along) - flat(on_line)};
    for (int e = 0; e < 2; ++e) {
      const auto end = meet(e == 0 ? *l0 : *l1, shared);
      if (!end) continue;
      t_sum[e] += (end->x() * u + end->y() * v).dot(along) - on_line.dot(along);
      ++t_count[e];
    }
  }
  if (t_count[0] > 0) v0 = on_line + t_sum[0] / t_count[0] * along;
  if (t_count[1] > 0) v1 = on_line + t_sum[1] / t_count[1] * along;
}

}  // namespace

std::optional<std::array<Point, 4>> tetrahedron_from_two_faces(
    const SolveInput& in, const std::vector<const DetectedPlane*>& faces, double cos_parallel) {
  if (faces.size() < 2) return std::nullopt;
  const DetectedPlane& a = *faces[0];
  const DetectedPlane& b = *faces[1];
  if (std::abs(a.plane.normal.dot(b.plane.normal)) > cos_parallel) return std::nullopt;
  const Eigen::Vector3d along = a.plane.normal.cross(b.plane.normal).normalized();
  Point centroid = Point::Zero();
  for (const Point& p : in.cloud) centroid += p / static_cast<double>(in.cloud.size());
  const auto on_line =
      geometry::intersect_three_planes(a.plane, b.plane, {along, -along.dot(centroid)});
  if (!on_line) return std::nullopt;
  const auto off_line = [&](const Point& p) {
    const Eigen::Vector3d d = p - *on_line;
    return (d - d.dot(along) * along).norm();
  };
  const double band = in.cfg.inlier_distance * in.resolution;
  double t_lo = std::numeric_limits<double>::infinity(), t_hi = -t_lo;
  std::array<Point, 2> apex;
  for (int k = 0; k < 2; ++k) {
    const DetectedPlane& f = k == 0 ? a : b;
    double farthest = -1.0;
    for (std::uint32_t i : f.inliers) {
      const double off = off_line(in.cloud[i]);
      if (off > farthest) {
        farthest = off;
        apex[k] = f.plane.project(in.cloud[i]);
      }
      if (off <= band) {
        const double t = (in.cloud[i] - *on_line).dot(along);
        t_lo = std::min(t_lo, t);
        t_hi = std::max(t_hi, t);
      }
    }
  }
  if (!(t_hi > t_lo)) return std::nullopt;
  Point v0 = *on_line + t_lo * along, v1 = *on_line + t_hi * along;
  refine_corners(in, a, b, *on_line, along, v0, v1, apex);
  for (int k = 0; k < 2; ++k) {
    const double triangle = 0.5 * (v1 - v0).cross(apex[k] - v0).norm();
    if (!(triangle > 0.0) || !(std::abs(face_hull_area(in.cloud, k == 0 ? a : b) / triangle -
                                        1.0) <= in.cfg.triangle_fill_tolerance))
      return std::nullopt;
  }
  // Each seen face is the outside of the solid: the other face's corner lies behind it.
  if (!(a.plane.signed_distance(apex[1]) < 0.0) || !(b.plane.signed_distance(apex[0]) < 0.0))
    return std::nullopt;
  return std::array<Point, 4>{v0, v1, apex[0], apex[1]};
}

}  // namespace cloudshape::pipeline::detail
