#include "segment/line_neighbourhoods.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/kdtree.hpp"
#include "geometry/pca.hpp"

namespace cloudshape::segment {
namespace {

double spread_of(const geometry::Pca& pca) {
  const double major = std::max(0.0, pca.eigenvalues(2));
  return major > 0.0 ? std::sqrt(std::max(0.0, pca.eigenvalues(1)) / major) : 0.0;
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> widen_line_neighbourhoods(
    const PointList& nodes, const std::vector<char>& linear_knn, const std::vector<Eigen::Vector3d>& line_of,
    const config::SegmentConfig& cfg, std::vector<Eigen::Vector3d>& normals, std::vector<double>& curvature) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> across;
  const std::size_t k0 = std::min<std::size_t>(
      nodes.size(), static_cast<std::size_t>(std::max<std::int64_t>(3, cfg.normal_neighbours)));
  const std::size_t k_max = std::min<std::size_t>(
      nodes.size(), static_cast<std::size_t>(std::max<std::int64_t>(0, cfg.line_max_neighbours)));
  if (k_max <= k0) return across;
  // Most clouds have no node on a line: no tree for them.
  const bool any = std::any_of(linear_knn.begin(), linear_knn.end(), [](char c) { return c != 0; }) ||
                   std::any_of(line_of.begin(), line_of.end(), [](const Eigen::Vector3d& d) { return d.squaredNorm() > 0.0; });
  if (!any) return across;
  const geometry::KdTree tree(nodes);
  const double cos_off_line = std::cos(45.0 * 3.14159265358979323846 / 180.0);
  std::vector<std::uint32_t> idx;
  for (std::uint32_t n = 0; n < nodes.size(); ++n) {
    bool need_normal = linear_knn[n] != 0;
    bool need_edge = line_of[n].squaredNorm() > 0.0;
    for (std::size_t k = std::min(k_max, 2 * k0); (need_normal || need_edge); k = std::min(k_max, 2 * k)) {
      tree.knn(nodes[n], k, idx);
      if (need_normal) {
        const geometry::Pca pca = geometry::compute_pca(nodes, idx);
        if (spread_of(pca) >= cfg.line_spread) {
          normals[n] = pca.eigenvectors.col(0).normalized();
          curvature[n] = pca.surface_variation();
          need_normal = false;
        }
      }
      if (need_edge) {
        for (std::uint32_t m : idx) {
          const Eigen::Vector3d d = nodes[m] - nodes[n];
          const double length = d.norm();
          if (length > 0.0 && std::abs(d.dot(line_of[n])) < cos_off_line * length) {
            across.emplace_back(n, m);
            need_edge = false;
            break;
          }
        }
      }
      if (k == k_max) break;
    }
  }
  return across;
}

}  // namespace cloudshape::segment
