#include "pipeline/planes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "geometry/circle.hpp"
#include "pipeline/plane_patch.hpp"
#include "pipeline/view_noise.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cloudshape::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::uint32_t> points_near(const PointList& cloud,
                                       const std::vector<std::uint32_t>& pool,
                                       const geometry::Plane& plane, double threshold) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i : pool)
    if (std::abs(plane.signed_distance(cloud[i])) < threshold) out.push_back(i);
  return out;
}

// The points that score the hypotheses, one array per coordinate, so that the count below runs
// over contiguous values.
struct ScoringPoints {
  std::vector<double> x, y, z;
  void add(const Point& p) { x.push_back(p.x()), y.push_back(p.y()), z.push_back(p.z()); }
  std::size_t size() const { return x.size(); }
};

// Points in [begin, end) within `threshold` of the plane, with Plane::signed_distance's
// arithmetic in its order ((nx x + ny y) + nz z) + d: two points at a time where SSE2 is (every
// x86-64), the same IEEE operations per lane, so the same counts (the build enables no FMA that
// could fuse one path's multiply-adds and not the other's).
std::size_t count_near(const ScoringPoints& pts, std::size_t begin, std::size_t end, const geometry::Plane& plane,
                       double threshold) {
  const double nx = plane.normal.x(), ny = plane.normal.y(), nz = plane.normal.z(), d = plane.offset;
  std::size_t count = 0;
  std::size_t i = begin;
#if defined(__SSE2__)
  const __m128d vx = _mm_set1_pd(nx), vy = _mm_set1_pd(ny), vz = _mm_set1_pd(nz), vd = _mm_set1_pd(d);
  const __m128d limit = _mm_set1_pd(threshold);
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  for (; i + 2 <= end; i += 2) {
    __m128d v = _mm_add_pd(_mm_mul_pd(vx, _mm_loadu_pd(&pts.x[i])), _mm_mul_pd(vy, _mm_loadu_pd(&pts.y[i])));
    v = _mm_add_pd(_mm_add_pd(v, _mm_mul_pd(vz, _mm_loadu_pd(&pts.z[i]))), vd);
    const int inside = _mm_movemask_pd(_mm_cmplt_pd(_mm_and_pd(v, magnitude), limit));
    count += static_cast<std::size_t>((inside & 1) + (inside >> 1));
  }
#endif
  for (; i < end; ++i) count += std::abs(nx * pts.x[i] + ny * pts.y[i] + nz * pts.z[i] + d) < threshold ? 1 : 0;
  return count;
}

// Points within `threshold` of the plane; counting stops, with a count of at most `to_beat`,
// once the points left could no longer lift it above `to_beat` (only a higher score replaces
// the best hypothesis, so the choice is the one full counts make).
std::size_t subset_score(const ScoringPoints& pts, const geometry::Plane& plane, double threshold,
                         std::size_t to_beat) {
  constexpr std::size_t kBlock = 256;
  std::size_t score = 0;
  for (std::size_t begin = 0; begin < pts.size(); begin += kBlock) {
    if (score + (pts.size() - begin) <= to_beat) break;
    score += count_near(pts, begin, std::min(pts.size(), begin + kBlock), plane, threshold);
  }
  return score;
}

// Best plane hypothesis by RANSAC: triples drawn from one local neighbourhood (a triple
// spread over the cloud rarely lies on one face), scored on a fixed random subset.
std::optional<geometry::Plane> best_hypothesis(const PointList& cloud,
                                               const geometry::KdTree& tree,
                                               const std::vector<std::int32_t>& labels,
                                               const std::vector<std::uint32_t>& remaining,
                                               double resolution, const config::PlanesConfig& cfg,
                                               std::mt19937_64& rng) {
  std::uniform_int_distribution<std::size_t> pick(0, remaining.size() - 1);
  ScoringPoints subset;
  const auto samples = static_cast<std::size_t>(std::max<std::int64_t>(1, cfg.score_samples));
  if (remaining.size() <= samples) {
    for (std::uint32_t i : remaining) subset.add(cloud[i]);
  } else {
    for (std::size_t i = 0; i < samples; ++i) subset.add(cloud[remaining[pick(rng)]]);
  }
  // Scored at the fine threshold: a tangent strip of a curved surface is as wide as the
  // threshold allows (width ~ sqrt(threshold)), a true face is not, so the fine score ranks
  // faces above strips and caps are found before the curved side is cut up.
  const double threshold = cfg.fine_threshold * resolution;
  std::optional<geometry::Plane> best;
  std::size_t best_score = 0;
  std::vector<std::uint32_t> near;
  for (std::int64_t it = 0; it < cfg.ransac_iterations; ++it) {
    const std::uint32_t a = remaining[pick(rng)];
    tree.radius(cloud[a], cfg.sample_radius * resolution, near);
    if (near.size() < 3) continue;
    std::uniform_int_distribution<std::size_t> pick_near(0, near.size() - 1);
    std::uint32_t b = a, c = a;
    for (int tries = 0; tries < 20 && (b == a || labels[b] >= 0); ++tries) b = near[pick_near(rng)];
    for (int tries = 0; tries < 20 && (c == a || c == b || labels[c] >= 0); ++tries)
      c = near[pick_near(rng)];
    if (b == a || c == a || c == b || labels[b] >= 0 || labels[c] >= 0) continue;
    const auto plane = geometry::plane_through(cloud[a], cloud[b], cloud[c]);
    if (!plane) continue;
    if (const std::size_t score = subset_score(subset, *plane, threshold, best_score); score > best_score) {
      best_score = score;
      best = plane;
    }
  }
  return best;
}

}  // namespace

std::vector<std::uint32_t> find_plane_boundary(const geometry::KdTree& tree,
                                               const std::vector<std::int32_t>& labels,
                                               std::int32_t label, const geometry::Plane& plane,
                                               const std::vector<std::uint32_t>& candidates,
                                               const config::PlanesConfig& cfg, parallel::ThreadPool* pool) {
  const PointList& cloud = tree.points();
  Eigen::Vector3d u, v;
  geometry::plane_basis(plane.normal, u, v);
  const double gap_limit = cfg.boundary_gap_degrees * kPi / 180.0;
  // Each block of candidates keeps its own boundary points; the blocks are joined in order.
  constexpr std::size_t kGrain = 256;
  std::vector<std::vector<std::uint32_t>> found((candidates.size() + kGrain - 1) / kGrain);
  parallel::for_blocks(pool, candidates.size(), kGrain, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint32_t>& out = found[begin / kGrain];
    std::vector<std::uint32_t> nb;
    std::vector<double> angles;
    for (std::size_t c = begin; c < end; ++c) {
      const std::uint32_t i = candidates[c];
      tree.knn(cloud[i], static_cast<std::size_t>(cfg.boundary_neighbours) + 1, nb);
      angles.clear();
      for (std::uint32_t j : nb) {
        if (j == i || labels[j] != label) continue;
        const Eigen::Vector3d d = cloud[j] - cloud[i];
        angles.push_back(std::atan2(d.dot(v), d.dot(u)));
      }
      if (angles.size() < 2) {
        out.push_back(i);
        continue;
      }
      if (geometry::widest_angular_gap(angles) > gap_limit) out.push_back(i);
    }
  });
  std::vector<std::uint32_t> out;
  for (const auto& block : found) out.insert(out.end(), block.begin(), block.end());
  return out;
}

std::vector<PlaneLine> find_plane_lines(const PointList& cloud,
                                        const std::vector<DetectedPlane>& planes,
                                        double resolution, const config::PlanesConfig& cfg) {
  std::vector<PlaneLine> lines;
  const double max_cos = std::cos(cfg.min_line_angle_degrees * kPi / 180.0);
  const double near = cfg.line_distance * resolution;
  auto support = [&](const DetectedPlane& p, const geometry::Line& line, double& lo, double& hi) {
    std::int64_t n = 0;
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (std::uint32_t i : p.boundary) {
      const Eigen::Vector3d d = cloud[i] - line.point;
      const double t = d.dot(line.direction);
      if ((d - t * line.direction).norm() > near) continue;
      lo = std::min(lo, t);
      hi = std::max(hi, t);
      ++n;
    }
    return n;
  };
  for (std::size_t a = 0; a < planes.size(); ++a) {
    for (std::size_t b = a + 1; b < planes.size(); ++b) {
      if (std::abs(planes[a].plane.normal.dot(planes[b].plane.normal)) > max_cos) continue;
      const auto line = geometry::intersect_planes(planes[a].plane, planes[b].plane);
      if (!line) continue;
      double lo_a, hi_a, lo_b, hi_b;
      if (support(planes[a], *line, lo_a, hi_a) < cfg.line_min_support) continue;
      if (support(planes[b], *line, lo_b, hi_b) < cfg.line_min_support) continue;
      const double lo = std::max(lo_a, lo_b);
      const double hi = std::min(hi_a, hi_b);
      if (hi - lo < resolution) continue;
      lines.push_back({*line, lo, hi, static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
    }
  }
  return lines;
}

PlaneSegmentation segment_planes(const PointList& cloud, double resolution,
                                 const config::PlanesConfig& cfg,
                                 const geometry::KdTree* shared_tree, parallel::ThreadPool* pool,
                                 const std::optional<Point>& viewpoint) {
  PlaneSegmentation out;
  out.labels.assign(cloud.size(), -1);
  if (cloud.size() < 3 || !(resolution > 0.0)) return out;
  std::optional<geometry::KdTree> own_tree;
  const geometry::KdTree& tree = shared_tree ? *shared_tree : own_tree.emplace(cloud);
  std::mt19937_64 rng(cfg.seed);
  const std::size_t min_points = std::max<std::size_t>(
      static_cast<std::size_t>(std::max<std::int64_t>(3, cfg.min_plane_points)),
      static_cast<std::size_t>(cfg.min_plane_fraction * static_cast<double>(cloud.size())));
  const double coarse = cfg.coarse_threshold * resolution;
  // Seen by a sensor whose noise exceeds the fine band, the band takes cfg.noise_sigmas of that
  // noise (read along the rays: the nearest points in space read a third of it): a band narrower
  // than the noise takes a face apart in parallel layers, which pass for a box's opposite faces or
  // a cylinder's caps.
  double fine = cfg.fine_threshold * resolution;
  if (viewpoint && cfg.noise_sigmas > 0.0) {
    out.view_noise = noise_along_view(cloud, *viewpoint, kViewNoiseRays);
    fine = std::clamp(cfg.noise_sigmas * out.view_noise, fine, std::max(fine, coarse));
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Point& p : cloud) centroid += p;
  centroid /= static_cast<double>(cloud.size());

  std::vector<std::uint32_t> remaining(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) remaining[i] = static_cast<std::uint32_t>(i);
  std::vector<std::vector<std::uint32_t>> border_candidates;
  std::int64_t rejected_in_row = 0;
  std::int64_t failures = 0;
  while (static_cast<std::int64_t>(out.planes.size()) < cfg.max_planes &&
         remaining.size() >= min_points && failures < 3) {
    const auto hypothesis = best_hypothesis(cloud, tree, out.labels, remaining, resolution, cfg, rng);
    if (!hypothesis) break;
    // Thesis 3.1: the coarse threshold finds the plane, the fine one refits it without
    // the band it wrongly took from the neighbouring faces (Fig. 3.2).
    auto inliers = points_near(cloud, remaining, *hypothesis, coarse);
    if (inliers.size() < 3) { ++failures; continue; }
    geometry::Plane plane = geometry::fit_plane_least_squares(cloud, inliers);
    for (int pass = 0; pass < 2; ++pass) {
      inliers = points_near(cloud, remaining, plane, fine);
      if (inliers.size() < 3) break;
      plane = geometry::fit_plane_least_squares(cloud, inliers);
    }
    inliers = points_near(cloud, remaining, plane, fine);
    detail::PatchRaster raster =
        detail::rasterise_patch(cloud, inliers, plane, cfg.connectivity * resolution);
    if (raster.largest.size() < min_points) {
      ++failures;
      continue;
    }
    failures = 0;
    DetectedPlane detected;
    detected.plane = geometry::fit_plane_least_squares(cloud, raster.largest);
    Eigen::Vector3d patch_centroid = Eigen::Vector3d::Zero();
    for (std::uint32_t i : raster.largest) patch_centroid += cloud[i];
    patch_centroid /= static_cast<double>(raster.largest.size());
    if (detected.plane.normal.dot(patch_centroid - centroid) < 0.0) {
      detected.plane.normal = -detected.plane.normal;
      detected.plane.offset = -detected.plane.offset;
    }
    const detail::PatchCurvature bend =
        detail::measure_patch_curvature(cloud, raster.largest, detected.plane);
    detected.curvature_sagitta = bend.sagitta / resolution;
    detected.curvature_radius_ratio = bend.radius_to_extent;
    detected.is_face = bend.sagitta < cfg.face_max_sagitta * fine ||
                       bend.radius_to_extent > cfg.face_min_radius_ratio;
    const auto label = static_cast<std::int32_t>(out.planes.size());
    for (std::uint32_t i : raster.largest) out.labels[i] = label;
    detected.inliers = std::move(raster.largest);
    border_candidates.push_back(std::move(raster.border_candidates));
    out.planes.push_back(std::move(detected));
    remaining.erase(std::remove_if(remaining.begin(), remaining.end(),
                                   [&](std::uint32_t i) { return out.labels[i] >= 0; }),
                    remaining.end());
    rejected_in_row = out.planes.back().is_face ? 0 : rejected_in_row + 1;
    if (rejected_in_row >= cfg.max_rejected_in_row) break;
  }
  for (std::size_t k = 0; k < out.planes.size(); ++k)
    out.planes[k].boundary = find_plane_boundary(tree, out.labels, static_cast<std::int32_t>(k),
                                                 out.planes[k].plane, border_candidates[k], cfg, pool);
  out.lines = find_plane_lines(cloud, out.planes, resolution, cfg);
  return out;
}

}  // namespace cloudshape::pipeline
