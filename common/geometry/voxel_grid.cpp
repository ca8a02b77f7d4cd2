#include "geometry/voxel_grid.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/detail/flat_hash.hpp"
#include "geometry/grid_neighbours.hpp"
#include "geometry/kdtree.hpp"

namespace cloudshape::geometry {
namespace {

constexpr std::size_t kGridFrom = 50000;

}  // namespace

Bounds bounding_box(const PointList& points) {
  Bounds b;
  if (points.empty()) return b;
  b.min = b.max = points.front();
  for (const Point& p : points) {
    b.min = b.min.cwiseMin(p);
    b.max = b.max.cwiseMax(p);
  }
  return b;
}

PointList voxel_grid_downsample(const PointList& points, double voxel_size,
                                int min_occupied_neighbours, std::size_t* isolated, const Bounds* bounds) {
  if (isolated) *isolated = 0;
  if (!(voxel_size > 0.0) || points.empty()) return points;
  const Bounds b = bounds ? *bounds : bounding_box(points);
  const double inv = 1.0 / voxel_size;
  // 21 bits per axis (one voxel of margin each side for the neighbour test). A denormal voxel
  // (inv = inf) or coordinates whose differences overflow give no grid (found by fuzz_ingest:
  // 0 * inf = NaN would be cast to an integer below).
  const Eigen::Vector3d extent = (b.max - b.min) * inv;
  if (!std::isfinite(inv) || !extent.allFinite() || !(extent.maxCoeff() < double((1 << 21) - 3))) return points;
  auto key_of = [](std::uint64_t ix, std::uint64_t iy, std::uint64_t iz) {
    return (ix << 42) | (iy << 21) | iz;
  };

  struct Acc {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::uint32_t count = 0;
    std::uint64_t key = 0;
  };
  detail::CellMap slot(points.size() / 4 + 16);
  std::vector<Acc> acc;
  acc.reserve(points.size() / 4 + 16);
  for (const Point& p : points) {
    const Eigen::Vector3d q = (p - b.min) * inv;
    const std::uint64_t key = key_of(static_cast<std::uint64_t>(q.x()) + 1,
                                     static_cast<std::uint64_t>(q.y()) + 1,
                                     static_cast<std::uint64_t>(q.z()) + 1);
    bool inserted = false;
    const std::uint32_t s = slot.find_or_insert(key, static_cast<std::uint32_t>(acc.size()), inserted);
    if (inserted) {
      acc.emplace_back();
      acc.back().key = key;
    }
    acc[s].sum += p;
    ++acc[s].count;
  }
  constexpr std::uint64_t kMask = (1u << 21) - 1;
  std::vector<char> lonely(acc.size(), 0);
  std::size_t lonely_count = 0;
  if (min_occupied_neighbours > 0) {
    for (std::size_t v = 0; v < acc.size(); ++v) {
      const std::uint64_t key = acc[v].key;
      const std::uint64_t ix = key >> 42, iy = (key >> 21) & kMask, iz = key & kMask;
      // Only whether `min_occupied_neighbours` are reached matters: the search stops there.
      int occupied = 0;
      for (int dx = -1; dx <= 1 && occupied < min_occupied_neighbours; ++dx)
        for (int dy = -1; dy <= 1 && occupied < min_occupied_neighbours; ++dy)
          for (int dz = -1; dz <= 1 && occupied < min_occupied_neighbours; ++dz)
            if ((dx || dy || dz) &&
                slot.find(key_of(ix + dx, iy + dy, iz + dz)) != detail::CellMap::kAbsent)
              ++occupied;
      lonely[v] = occupied < min_occupied_neighbours;
      lonely_count += lonely[v];
    }
    // Many lonely voxels mean the grid is finer than the cloud's own sampling, not that
    // the cloud is full of outliers: then nothing is dropped.
    if (lonely_count * 4 > acc.size()) std::fill(lonely.begin(), lonely.end(), 0), lonely_count = 0;
  }
  if (isolated) *isolated = lonely_count;
  PointList out;
  out.reserve(acc.size() - lonely_count);
  for (std::size_t v = 0; v < acc.size(); ++v)
    if (!lonely[v]) out.push_back(acc[v].sum / static_cast<double>(acc[v].count));
  return out;
}

std::size_t count_occupied_voxels(const PointList& points, double voxel_size, const Bounds* bounds) {
  if (!(voxel_size > 0.0) || points.empty()) return points.size();
  const Bounds b = bounds ? *bounds : bounding_box(points);
  const double inv = 1.0 / voxel_size;
  // The same keys and the same validity as voxel_grid_downsample's.
  const Eigen::Vector3d extent = (b.max - b.min) * inv;
  if (!std::isfinite(inv) || !extent.allFinite() || !(extent.maxCoeff() < double((1 << 21) - 3))) return points.size();
  // Room for a voxel per point: the finest voxel of a search often holds one or two points, and
  // a map that grows rehashes every key it has.
  detail::CellMap slot(points.size() + 16);
  std::uint32_t occupied = 0;
  for (const Point& p : points) {
    const Eigen::Vector3d q = (p - b.min) * inv;
    const std::uint64_t key = ((static_cast<std::uint64_t>(q.x()) + 1) << 42) |
                              ((static_cast<std::uint64_t>(q.y()) + 1) << 21) | (static_cast<std::uint64_t>(q.z()) + 1);
    bool inserted = false;
    slot.find_or_insert(key, occupied, inserted);
    occupied += inserted ? 1 : 0;
  }
  return occupied;
}

namespace {

std::vector<std::uint32_t> spread_sample(std::size_t size, std::size_t max_samples) {
  const std::size_t step = std::max<std::size_t>(1, size / std::max<std::size_t>(1, max_samples));
  std::vector<std::uint32_t> sample;
  for (std::size_t i = 0; i < size; i += step) sample.push_back(static_cast<std::uint32_t>(i));
  return sample;
}

double mean_over_grid(const PointList& points, const std::vector<std::uint32_t>& sample, parallel::ThreadPool* pool,
                      const Bounds* bounds) {
  double sum = 0.0;
  for (double d : nearest_other_distances(points, sample, pool, bounds)) sum += d;
  return sum / static_cast<double>(sample.size());
}

double mean_over_tree(const KdTree& tree, const std::vector<std::uint32_t>& sample) {
  double sum = 0.0;
  std::vector<std::uint32_t> idx;
  std::vector<double> d2;
  for (std::uint32_t i : sample) {
    tree.knn(tree.points()[i], 2, idx, &d2);
    sum += std::sqrt(d2[1]);
  }
  return sum / static_cast<double>(sample.size());
}

}  // namespace

// The grid's one binning pass beats a kd-tree's sorting on big clouds only; both are exact.
double mean_nearest_neighbour_distance(const PointList& points, std::size_t max_samples, parallel::ThreadPool* pool,
                                       const Bounds* bounds) {
  if (points.size() < 2) return 0.0;
  const std::vector<std::uint32_t> sample = spread_sample(points.size(), max_samples);
  if (points.size() > kGridFrom) return mean_over_grid(points, sample, pool, bounds);
  return mean_over_tree(KdTree(points), sample);
}

double mean_nearest_neighbour_distance(const KdTree& tree, std::size_t max_samples, parallel::ThreadPool* pool) {
  const PointList& points = tree.points();
  if (points.size() < 2) return 0.0;
  const std::vector<std::uint32_t> sample = spread_sample(points.size(), max_samples);
  if (points.size() > kGridFrom) return mean_over_grid(points, sample, pool, nullptr);
  return mean_over_tree(tree, sample);
}

}  // namespace cloudshape::geometry
