#include "segment/crease_overlap.hpp"

#include <algorithm>
#include <cmath>

namespace cloudshape::segment {

CreaseOverlap::CreaseOverlap(const NeighbourGraph& g, const std::vector<std::int32_t>& patch,
                             const std::vector<char>& surface, std::int32_t patches, double band)
    : g_(g),
      band_(band),
      members_(static_cast<std::size_t>(patches)),
      normal_(static_cast<std::size_t>(patches), Eigen::Vector3d::Zero()),
      centroid_(static_cast<std::size_t>(patches), Eigen::Vector3d::Zero()),
      spacing_(static_cast<std::size_t>(patches), 0.0) {
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (patch[n] < 0 || !surface[n]) continue;
    members_[patch[n]].push_back(n);
    normal_[patch[n]] += g.normals[n];
    centroid_[patch[n]] += g.nodes[n];
    spacing_[patch[n]] += g.spacing[n];
  }
  for (std::size_t p = 0; p < members_.size(); ++p) {
    if (members_[p].empty()) continue;
    const auto count = static_cast<double>(members_[p].size());
    if (normal_[p].norm() > 0.0) normal_[p].normalize();
    centroid_[p] /= count;
    spacing_[p] /= count;
  }
}

CreaseOverlap::Span CreaseOverlap::span_near(std::uint32_t p, std::uint32_t other, const Eigen::Vector3d& line,
                                             double band) const {
  std::vector<double> t;
  for (std::uint32_t n : members_[p]) {
    if (std::abs(normal_[other].dot(g_.nodes[n] - centroid_[other])) <= band) t.push_back(line.dot(g_.nodes[n]));
  }
  Span s;
  if (t.size() < 3) return s;
  const std::size_t cut = t.size() / 50;
  std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(cut), t.end());
  s.lo = t[cut];
  std::nth_element(t.begin(), t.end() - 1 - static_cast<std::ptrdiff_t>(cut), t.end());
  s.hi = t[t.size() - 1 - cut];
  s.valid = true;
  return s;
}

bool CreaseOverlap::shares_crease(std::uint32_t a, std::uint32_t b, double parallel_cos, double min_share) const {
  if (min_share <= 0.0 || members_[a].empty() || members_[b].empty()) return true;
  // Parallel or opposite (normals turned outward from a centroid flip on a non-convex solid's
  // faces): no crease line to judge along.
  if (std::abs(normal_[a].dot(normal_[b])) >= parallel_cos) return true;
  const Eigen::Vector3d line = normal_[a].cross(normal_[b]).normalized();
  const double band = band_ * std::max(spacing_[a], spacing_[b]);
  const Span sa = span_near(a, b, line, band);
  const Span sb = span_near(b, a, line, band);
  if (!sa.valid || !sb.valid) return true;
  const double shorter = std::min(sa.hi - sa.lo, sb.hi - sb.lo);
  return std::min(sa.hi, sb.hi) - std::max(sa.lo, sb.lo) >= min_share * shorter;
}

}  // namespace cloudshape::segment
