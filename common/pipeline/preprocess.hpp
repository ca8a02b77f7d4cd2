// Stage 1: from a raw cloud to a filtered one: voxel grid (centroid per voxel) with an
// isolated-voxel outlier filter, optional statistical outlier removal and smoothing, the resolution.
#pragma once

#include <cstddef>
#include <memory>

#include "config/stage_configs.hpp"
#include "geometry/kdtree.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::pipeline {

struct PreprocessedCloud {
  PointList points;
  double resolution = 0.0;  // mean nearest-neighbour distance of `points`
  double voxel_size = 0.0;  // edge of the voxel grid actually used
  std::size_t outliers_removed = 0;  // isolated voxels plus statistical outliers
  // Over a copy of `points` (same indices): built for the resolution, kept for the object's
  // stages that need neighbours. Null when there are no points.
  std::shared_ptr<const geometry::KdTree> tree;
};

// Non-finite points must have been dropped by the reader. Never throws on content:
// too few points simply give a small (possibly empty) result. A `pool` shares a large cloud's
// passes (bounds, voxel counts) and the resolution's searches out: the same result.
PreprocessedCloud preprocess_cloud(const PointList& raw, const config::PreprocessConfig& cfg,
                                   parallel::ThreadPool* pool = nullptr);

// Statistical outlier removal: drops points whose mean distance to their k nearest
// neighbours exceeds the cloud's mean by `stddev_factor` standard deviations.
PointList remove_statistical_outliers(const PointList& points, std::size_t k, double stddev_factor,
                                      std::size_t* removed = nullptr);

// Projects every point whose k-neighbourhood is flatter than `max_curvature` onto that
// neighbourhood's least-squares plane; corners and edges are left as they are.
PointList smooth_flat_regions(const PointList& points, std::size_t k, double max_curvature);

}  // namespace cloudshape::pipeline
