// Which faces of a new shape hold the points of one view, and whether they determine the solid.
// Points are classified noise-free, by the face they were sampled on (nearest face geometry).
#include "view_faces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cloudshape::bench {

namespace {

std::size_t seen(const std::vector<std::size_t>& counts, std::size_t from, std::size_t to, std::size_t total) {
  std::size_t n = 0;
  for (std::size_t f = from; f < to; ++f)
    n += static_cast<double>(counts[f]) >= kSeenFaceShare * static_cast<double>(total) ? 1 : 0;
  return n;
}

double segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// Points within this fraction of the solid's extent of a cap's plane lie on the cap: sampled
// points sit on their face to rounding, far below it.
constexpr double kOnCap = 1e-7;

}  // namespace

ViewFaces prism_view_faces(const PointList& points, const geometry::Polygon2& polygon, double height,
                           const synth::Pose& pose) {
  const std::size_t n = polygon.size();
  ViewFaces v;
  v.counts.assign(n + 2, 0);  // the two caps, then side k from corner k to k+1
  for (const auto& p : points) {
    const Eigen::Vector3d local = pose.axes * (p - pose.center);
    if (std::abs(std::abs(local.x()) - 0.5 * height) <= kOnCap * height) {
      ++v.counts[local.x() > 0 ? 1 : 0];
      continue;
    }
    const Eigen::Vector2d uv(local.y(), local.z());
    std::size_t best = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
      const double d = segment_distance(uv, polygon[k], polygon[(k + 1) % n]);
      if (d < nearest) nearest = d, best = k;
    }
    ++v.counts[2 + best];
  }
  const std::size_t caps = seen(v.counts, 0, 2, points.size());
  const std::size_t sides = seen(v.counts, 2, n + 2, points.size());
  v.determines = caps >= 1 && sides >= 1;
  char note[96];
  std::snprintf(note, sizeof note, "faces seen: caps %zu, sides %zu of %zu", caps, sides, n);
  v.note = note;
  return v;
}

ViewFaces frustum_view_faces(const PointList& points, double height, const synth::Pose& pose) {
  ViewFaces v;
  v.counts.assign(3, 0);  // larger end, smaller end, side
  for (const auto& p : points) {
    const double x = pose.axes.row(0).dot(p - pose.center);
    ++v.counts[std::abs(x) <= kOnCap * height ? 0 : std::abs(x - height) <= kOnCap * height ? 1 : 2];
  }
  v.determines = seen(v.counts, 2, 3, points.size()) == 1;
  char note[96];
  std::snprintf(note, sizeof note, "faces seen: large end %zu, small end %zu, side %zu",
                seen(v.counts, 0, 1, points.size()), seen(v.counts, 1, 2, points.size()),
                seen(v.counts, 2, 3, points.size()));
  v.note = note;
  return v;
}

ViewFaces tetrahedron_view_faces(const PointList& points, const std::array<Eigen::Vector3d, 4>& corners) {
  ViewFaces v;
  v.counts.assign(4, 0);  // face k: the one opposite corner k
  std::array<Eigen::Vector3d, 4> normal;
  for (int k = 0; k < 4; ++k) {
    const auto& a = corners[(k + 1) % 4];
    normal[k] = (corners[(k + 2) % 4] - a).cross(corners[(k + 3) % 4] - a).normalized();
  }
  for (const auto& p : points) {
    int best = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
      const double d = std::abs(normal[k].dot(p - corners[(k + 1) % 4]));
      if (d < nearest) nearest = d, best = k;
    }
    ++v.counts[best];
  }
  const std::size_t faces = seen(v.counts, 0, 4, points.size());
  v.determines = faces >= 2;
  char note[64];
  std::snprintf(note, sizeof note, "faces seen: %zu of 4", faces);
  v.note = note;
  return v;
}

}  // namespace cloudshape::bench
