#include "pipeline/split_objects.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "geometry/detail/flat_hash.hpp"
#include "geometry/detail/union_find.hpp"
#include "geometry/voxel_grid.hpp"
#include "pipeline/support_plane.hpp"

namespace cloudshape::pipeline {
using geometry::detail::UnionFind;

// Spread (standard deviation) of the points across their longest direction: the second
// principal axis. A strip along a silhouette edge has almost none.
double spread_across(const PointList& points) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : points) cov.noalias() += (p - mean) * (p - mean).transpose();
  cov /= static_cast<double>(points.size());
  const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();
  return std::sqrt(std::max(eig(1), 0.0));
}

std::vector<PointList> connected_components(const PointList& points, double cell) {
  if (points.empty() || !(cell > 0.0)) return {points};
  const geometry::Bounds b = geometry::bounding_box(points);
  if (!(((b.max - b.min) / cell).maxCoeff() < double((1 << 20) - 2))) return {points};

  auto key_of = [](std::uint64_t x, std::uint64_t y, std::uint64_t z) { return (x << 42) | (y << 21) | z; };
  geometry::detail::CellMap cells(points.size() / 2 + 16);
  std::vector<std::uint64_t> cell_keys;
  std::vector<std::uint32_t> cell_of(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d q = (points[i] - b.min) / cell;
    const std::uint64_t key = key_of(static_cast<std::uint64_t>(q.x()) + 1, static_cast<std::uint64_t>(q.y()) + 1,
                                     static_cast<std::uint64_t>(q.z()) + 1);
    bool inserted = false;
    cell_of[i] = cells.find_or_insert(key, static_cast<std::uint32_t>(cell_keys.size()), inserted);
    if (inserted) cell_keys.push_back(key);
  }
  UnionFind uf(cell_keys.size());
  constexpr std::uint64_t kMask = (1u << 21) - 1;
  for (std::size_t c = 0; c < cell_keys.size(); ++c) {
    const std::uint64_t x = cell_keys[c] >> 42, y = (cell_keys[c] >> 21) & kMask, z = cell_keys[c] & kMask;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const std::uint32_t other = cells.find(key_of(x + dx, y + dy, z + dz));
          if (other != geometry::detail::CellMap::kAbsent) uf.unite(static_cast<std::uint32_t>(c), other);
        }
  }
  std::vector<std::uint32_t> root_to_component(cell_keys.size(), ~0u);
  std::vector<PointList> parts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t root = uf.find(cell_of[i]);
    if (root_to_component[root] == ~0u) {
      root_to_component[root] = static_cast<std::uint32_t>(parts.size());
      parts.emplace_back();
    }
    parts[root_to_component[root]].push_back(points[i]);
  }
  std::sort(parts.begin(), parts.end(), [](const PointList& a, const PointList& b) { return a.size() > b.size(); });
  return parts;
}

std::vector<PointList> split_objects(const PointList& scene, double resolution,
                                     const config::PreprocessConfig& cfg, std::size_t* dropped,
                                     bool* support_removed) {
  if (dropped) *dropped = 0;
  // The table or floor would join every object standing on it into one.
  const PointList points = remove_support_plane(scene, resolution, cfg, support_removed);
  const double cell = cfg.object_gap * resolution;
  if (!cfg.split_objects || points.empty() || !(cell > 0.0)) return {points};
  std::vector<PointList> parts = connected_components(points, cell);
  if (parts.size() <= 1) return parts;
  const auto min_size = static_cast<std::size_t>(std::ceil(cfg.min_object_fraction * static_cast<double>(points.size())));
  std::vector<PointList> kept;
  const double largest = static_cast<double>(parts.front().size());
  const auto is_fragment = [&](const PointList& part) {
    return static_cast<double>(part.size()) < cfg.fragment_max_share * largest &&
           spread_across(part) < cfg.fragment_max_width * resolution;
  };
  for (auto& part : parts) {
    if (kept.empty() || (part.size() >= std::max<std::size_t>(1, min_size) && !is_fragment(part)))
      kept.push_back(std::move(part));
    else if (dropped)
      *dropped += part.size();
  }
  return kept;
}

}  // namespace cloudshape::pipeline
