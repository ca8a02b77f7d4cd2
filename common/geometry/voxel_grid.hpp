// Voxel-grid downsampling (one centroid per occupied voxel) and the cloud
// resolution (mean distance to the nearest neighbour, thesis 3.4).
#pragma once

#include <optional>

#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::geometry {

class KdTree;

struct Bounds {
  Point min = Point::Zero();
  Point max = Point::Zero();
  double diagonal() const { return (max - min).norm(); }
};
// Over points[0], points[stride], points[2 * stride], ... (a strided subsample, not copied).
// A `pool` folds blocks of a large cloud side by side: the same bounds.
Bounds bounding_box(const PointList& points, std::size_t stride = 1, parallel::ThreadPool* pool = nullptr);

// Replaces the points of each cubic voxel of edge `voxel_size` by their centroid.
// voxel_size <= 0 returns the input unchanged. With min_occupied_neighbours > 0, voxels
// with fewer occupied voxels among their 26 neighbours are dropped as isolated (a radius
// outlier filter at the voxel's scale) and counted in *isolated; unless more than a quarter
// of the voxels are isolated, which means the grid is finer than the cloud's sampling.
// `bounds`, if given, must be bounding_box(points) (a caller that has it saves the pass).
PointList voxel_grid_downsample(const PointList& points, double voxel_size,
                                int min_occupied_neighbours = 0, std::size_t* isolated = nullptr,
                                const Bounds* bounds = nullptr);

// voxel_grid_downsample(points, voxel_size).size() without building the points: for searches
// of the voxel size that only count (`bounds` as above). With a `stride`, of the subsample
// points[0], points[stride], ... (`bounds` then bounding_box(points, stride)).
// A `pool` counts a large cloud's parts side by side: the same count.
std::size_t count_occupied_voxels(const PointList& points, double voxel_size, const Bounds* bounds = nullptr,
                                  std::size_t stride = 1, parallel::ThreadPool* pool = nullptr);

// voxel_grid_downsample(points, voxel_size, min_occupied_neighbours).size() (isolated voxels left
// out as there) without building the points, for a search of the voxel size over the whole cloud;
// nothing where a bit per voxel would take more than 8 bytes a point, or a point lies outside
// `bounds` (then only the grid tells). `bounds` and `pool` as above.
std::optional<std::size_t> downsampled_size(const PointList& points, double voxel_size,
                                            int min_occupied_neighbours,
                                            const Bounds* bounds = nullptr,
                                            parallel::ThreadPool* pool = nullptr);

// Mean distance from a point to its nearest other point, estimated on at most
// `max_samples` points spread evenly through the cloud. 0 for fewer than 2 points.
// A `pool` shares the grid's pass over the points out (large clouds): the same value. `bounds`
// as above.
double mean_nearest_neighbour_distance(const PointList& points, std::size_t max_samples = 4000,
                                       parallel::ThreadPool* pool = nullptr, const Bounds* bounds = nullptr);

// The same value over `tree`'s points, asking `tree` where the list version would build one.
double mean_nearest_neighbour_distance(const KdTree& tree, std::size_t max_samples = 4000,
                                       parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::geometry
