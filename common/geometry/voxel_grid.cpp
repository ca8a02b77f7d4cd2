#include "geometry/voxel_grid.hpp"

#include <cmath>
#include <unordered_map>

#include "geometry/kdtree.hpp"

namespace cloudshape::geometry {

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

PointList voxel_grid_downsample(const PointList& points, double voxel_size) {
  if (!(voxel_size > 0.0) || points.empty()) return points;
  const Bounds b = bounding_box(points);
  const double inv = 1.0 / voxel_size;
  // 21 bits per axis; a grid finer than that would not reduce anything anyway.
  const Eigen::Vector3d extent = (b.max - b.min) * inv;
  if (extent.maxCoeff() >= double(1 << 21)) return points;

  struct Acc {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::uint32_t count = 0;
  };
  std::unordered_map<std::uint64_t, std::uint32_t> slot;
  slot.reserve(points.size() / 2);
  std::vector<Acc> acc;
  acc.reserve(points.size() / 2);
  for (const Point& p : points) {
    const Eigen::Vector3d q = (p - b.min) * inv;
    const auto ix = static_cast<std::uint64_t>(q.x());
    const auto iy = static_cast<std::uint64_t>(q.y());
    const auto iz = static_cast<std::uint64_t>(q.z());
    const std::uint64_t key = (ix << 42) | (iy << 21) | iz;
    const auto [it, inserted] = slot.try_emplace(key, static_cast<std::uint32_t>(acc.size()));
    if (inserted) acc.emplace_back();
    Acc& a = acc[it->second];
    a.sum += p;
    ++a.count;
  }
  PointList out;
  out.reserve(acc.size());
  for (const Acc& a : acc) out.push_back(a.sum / static_cast<double>(a.count));
  return out;
}

double mean_nearest_neighbour_distance(const PointList& points, std::size_t max_samples) {
  if (points.size() < 2) return 0.0;
  const KdTree tree(points);
  const std::size_t step = std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, max_samples));
  std::vector<std::uint32_t> idx;
  std::vector<double> d2;
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < points.size(); i += step) {
    tree.knn(points[i], 2, idx, &d2);
    if (d2.size() < 2) continue;
    sum += std::sqrt(d2[1]);
    ++n;
  }
  return n ? sum / static_cast<double>(n) : 0.0;
}

}  // namespace cloudshape::geometry
