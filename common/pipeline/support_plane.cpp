#include "pipeline/support_plane.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <unordered_set>

#include "geometry/plane.hpp"

namespace cloudshape::pipeline {

// Extents of the given points' projections along u and v: {lo_u, hi_u, lo_v, hi_v}.
std::array<double, 4> footprint(const PointList& points, const std::vector<std::uint32_t>& idx,
                                const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  const double inf = std::numeric_limits<double>::infinity();
  std::array<double, 4> f{inf, -inf, inf, -inf};
  for (std::uint32_t i : idx) {
    const double a = points[i].dot(u), b = points[i].dot(v);
    f[0] = std::min(f[0], a), f[1] = std::max(f[1], a), f[2] = std::min(f[2], b), f[3] = std::max(f[3], b);
  }
  return f;
}

std::optional<geometry::Plane> dominant_plane(const PointList& points, double band, std::int64_t iterations,
                                              std::int64_t score_samples, std::uint64_t seed,
                                              const std::vector<Eigen::Vector3d>* normals, double min_cos) {
  const auto fits = [&](const geometry::Plane& plane, std::size_t i) {
    return std::abs(plane.signed_distance(points[i])) < band &&
           (!normals || std::abs((*normals)[i].dot(plane.normal)) >= min_cos);
  };
  if (points.size() < 3) return std::nullopt;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, points.size() - 1);
  const std::size_t step =
      std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, static_cast<std::size_t>(score_samples)));
  std::optional<geometry::Plane> best;
  std::size_t best_score = 0;
  for (std::int64_t it = 0; it < iterations; ++it) {
    const auto plane = geometry::plane_through(points[pick(rng)], points[pick(rng)], points[pick(rng)]);
    if (!plane) continue;
    std::size_t score = 0;
    for (std::size_t i = 0; i < points.size(); i += step) score += fits(*plane, i);
    if (score > best_score) best_score = score, best = plane;
  }
  if (!best) return std::nullopt;
  std::vector<std::uint32_t> on;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (fits(*best, i)) on.push_back(static_cast<std::uint32_t>(i));
  if (on.size() < 3) return std::nullopt;
  return geometry::fit_plane_least_squares(points, on);
}

bool surrounds(const std::array<double, 4>& plane, const std::array<double, 4>& objects, double margin) {
  const double du = margin * (objects[1] - objects[0]), dv = margin * (objects[3] - objects[2]);
  const int sides = (plane[0] <= objects[0] - du) + (plane[1] >= objects[1] + du) +
                    (plane[2] <= objects[2] - dv) + (plane[3] >= objects[3] + dv);
  return sides >= 3;
}

namespace {

// Share of the objects' points whose foot on the plane (their projection along its normal)
// falls where the plane itself was seen. A solid's face lies under nearly all the rest of the
// solid (a cone's base under its side, a box face under the side faces along its edge): ~1;
// a table is hidden where the objects stand on it (measured on the mOSD scenes: 0.5-0.8).
double shadowed_share(const PointList& points, const std::vector<std::uint32_t>& plane,
                      const std::vector<std::uint32_t>& objects, const Eigen::Vector3d& u,
                      const Eigen::Vector3d& v, double cell) {
  const auto key = [&](const Point& p) {
    const auto a = static_cast<std::int64_t>(std::floor(p.dot(u) / cell));
    const auto b = static_cast<std::int64_t>(std::floor(p.dot(v) / cell));
    return (static_cast<std::uint64_t>(a) << 32) ^ (static_cast<std::uint64_t>(b) & 0xffffffffu);
  };
  std::unordered_set<std::uint64_t> seen;
  for (std::uint32_t i : plane) seen.insert(key(points[i]));
  std::size_t over = 0;
  for (std::uint32_t i : objects) over += seen.count(key(points[i]));
  return objects.empty() ? 0.0 : static_cast<double>(over) / static_cast<double>(objects.size());
}

}  // namespace

PointList remove_support_plane(const PointList& points, double resolution,
                               const config::PreprocessConfig& cfg, bool* removed) {
  if (removed) *removed = false;
  if (!cfg.remove_support_plane || points.size() < 100 || !(resolution > 0.0)) return points;
  const double band = cfg.support_band * resolution;
  const auto fitted = dominant_plane(points, band, cfg.support_iterations, cfg.support_score_samples, 59907u);
  if (!fitted) return points;
  const geometry::Plane plane = *fitted;
  std::vector<std::uint32_t> on;
  std::array<std::vector<std::uint32_t>, 2> side;  // below, above
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = plane.signed_distance(points[i]);
    if (std::abs(d) < band) on.push_back(static_cast<std::uint32_t>(i));
    else side[d > 0.0].push_back(static_cast<std::uint32_t>(i));
  }
  const std::size_t rest = side[0].size() + side[1].size();
  if (static_cast<double>(on.size()) < cfg.support_min_share * static_cast<double>(points.size()) || rest == 0)
    return points;
  const auto& objects = side[side[1].size() >= side[0].size()];
  if (static_cast<double>(objects.size()) < cfg.support_one_sided * static_cast<double>(rest)) return points;
  Eigen::Vector3d u, v;
  geometry::plane_basis(plane.normal, u, v);
  if (!surrounds(footprint(points, on, u, v), footprint(points, objects, u, v), cfg.support_margin) ||
      shadowed_share(points, on, objects, u, v, cfg.support_cell * resolution) > cfg.support_max_overlap)
    return points;
  PointList kept;
  kept.reserve(objects.size());
  for (std::uint32_t i : objects) kept.push_back(points[i]);
  if (removed) *removed = true;
  return kept;
}

}  // namespace cloudshape::pipeline
