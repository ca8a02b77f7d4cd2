#include "pipeline/preprocess.hpp"

#include <cmath>
#include <numeric>
#include <optional>

#include "geometry/kdtree.hpp"
#include "geometry/pca.hpp"
#include "geometry/voxel_grid.hpp"

namespace cloudshape::pipeline {

PointList remove_statistical_outliers(const PointList& points, std::size_t k, double stddev_factor,
                                      std::size_t* removed) {
  if (removed) *removed = 0;
  if (points.size() <= k + 1 || k == 0) return points;
  const geometry::KdTree tree(points);
  std::vector<double> mean_dist(points.size());
  std::vector<std::uint32_t> idx;
  std::vector<double> d2;
  for (std::size_t i = 0; i < points.size(); ++i) {
    tree.knn(points[i], k + 1, idx, &d2);
    double s = 0.0;
    for (std::size_t j = 1; j < d2.size(); ++j) s += std::sqrt(d2[j]);
    mean_dist[i] = s / static_cast<double>(std::max<std::size_t>(1, d2.size() - 1));
  }
  const double mean =
      std::accumulate(mean_dist.begin(), mean_dist.end(), 0.0) / static_cast<double>(points.size());
  double var = 0.0;
  for (double m : mean_dist) var += (m - mean) * (m - mean);
  const double limit = mean + stddev_factor * std::sqrt(var / static_cast<double>(points.size()));
  PointList kept;
  kept.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    if (mean_dist[i] <= limit) kept.push_back(points[i]);
  if (removed) *removed = points.size() - kept.size();
  return kept;
}

PointList smooth_flat_regions(const PointList& points, std::size_t k, double max_curvature) {
  if (points.size() <= k || k < 3) return points;
  const geometry::KdTree tree(points);
  PointList out = points;
  std::vector<std::uint32_t> idx;
  for (std::size_t i = 0; i < points.size(); ++i) {
    tree.knn(points[i], k, idx);
    const geometry::Pca pca = geometry::compute_pca(points, idx);
    if (pca.surface_variation() >= max_curvature) continue;
    const Eigen::Vector3d n = pca.eigenvectors.col(0);
    out[i] = points[i] - n.dot(points[i] - pca.centroid) * n;
  }
  return out;
}

PreprocessedCloud preprocess_cloud(const PointList& raw, const config::PreprocessConfig& cfg,
                                   parallel::ThreadPool* pool) {
  PreprocessedCloud out;
  if (raw.empty()) return out;
  const geometry::Bounds bounds = geometry::bounding_box(raw, 1, pool);
  const double diagonal = bounds.diagonal();
  double voxel = cfg.voxel_divisions > 0.0 ? diagonal / cfg.voxel_divisions : 0.0;
  const int min_neighbours = static_cast<int>(cfg.isolated_voxel_neighbours);
  const auto budget = static_cast<std::size_t>(std::max<std::int64_t>(1, cfg.max_points));
  // Dense clouds: widen the voxel until the point budget holds; the area a voxel covers
  // scales with its edge squared, hence the square root. The size is first searched on
  // a sparse subsample (it can only occupy fewer voxels than the whole cloud), so the
  // whole cloud is usually gridded once.
  // The voxel that would hold about the budget, from `from` at which the points take `size`.
  const auto coarser = [&](double from, std::size_t size) {
    return (from > 0.0 ? from : diagonal / 1000.0) *
           std::sqrt(static_cast<double>(size) / static_cast<double>(budget)) * 1.02;
  };
  std::size_t stride = 1;
  if (cfg.max_points > 0 && raw.size() > budget) {
    stride = std::max<std::size_t>(1, raw.size() / (budget * 4));
    const geometry::Bounds sparse_bounds = geometry::bounding_box(raw, stride, pool);
    for (int attempt = 0; attempt < 4; ++attempt) {
      const std::size_t n = geometry::count_occupied_voxels(raw, voxel, &sparse_bounds, stride, pool);
      if (n <= budget) break;
      voxel = coarser(voxel, n);
    }
  }
  // Then the whole cloud: while its grid holds more than a fifth over the budget, a coarser
  // voxel (kCoarsenings times at most). A subsample of one point in kCountFirstStride or sparser
  // occupies too few voxels (a million points: 11 900 against the whole cloud's 16 400), so its
  // first grid would be thrown away: there a grid's size is counted where that can be (no points
  // built, the points' parts on the pool), and the cloud gridded at the voxel the grids would
  // have ended at; the same voxel and points as gridding each time.
  constexpr int kCoarsenings = 3;
  constexpr std::size_t kCountFirstStride = 8;
  std::size_t isolated = 0;
  std::optional<PointList> gridded;  // the grid at `voxel`, when it had to be built to be counted
  const auto size_at = [&](double v) {
    gridded.reset();
    if (stride >= kCountFirstStride) {
      if (const auto counted = geometry::downsampled_size(raw, v, min_neighbours, &bounds, pool))
        return *counted;
    }
    gridded = geometry::voxel_grid_downsample(raw, v, min_neighbours, &isolated, &bounds);
    return gridded->size();
  };
  std::size_t size = size_at(voxel);
  for (int attempt = 0; attempt < kCoarsenings && cfg.max_points > 0 && size > budget + budget / 5;
       ++attempt) {
    voxel = coarser(voxel, size);
    if (attempt + 1 < kCoarsenings) {
      size = size_at(voxel);
    } else {
      gridded.reset();  // the last voxel tried is kept whatever its size: gridded below
    }
  }
  PointList pts =
      gridded ? std::move(*gridded)
              : geometry::voxel_grid_downsample(raw, voxel, min_neighbours, &isolated, &bounds);
  out.voxel_size = voxel;
  out.outliers_removed = isolated;
  if (cfg.statistical_outliers) {
    std::size_t removed = 0;
    pts = remove_statistical_outliers(pts, static_cast<std::size_t>(cfg.outlier_neighbours),
                                      cfg.outlier_stddev, &removed);
    out.outliers_removed += removed;
  }
  if (cfg.smoothing)
    pts = smooth_flat_regions(pts, static_cast<std::size_t>(cfg.smoothing_neighbours),
                              cfg.smoothing_max_curvature);
  if (!pts.empty()) {
    out.tree = std::make_shared<const geometry::KdTree>(PointList(pts));
    out.resolution = geometry::mean_nearest_neighbour_distance(*out.tree, 4000, pool);
  }
  out.points = std::move(pts);
  return out;
}

}  // namespace cloudshape::pipeline
