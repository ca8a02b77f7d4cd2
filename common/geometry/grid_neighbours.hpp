// Exact nearest-neighbour searches on a uniform grid (an array of cells, or a hash map of them):
// linear binning instead of a kd-tree's sorting, for neighbours within a cell or two, same answers.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "geometry/voxel_grid.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::geometry {

// Distance from points[i] to its nearest other point, for each i of `queries`, in their order
// (exact: a query whose neighbour the grid cannot vouch for is searched again in wider cells, and
// one those cannot vouch for either by a scan or a kd-tree).
// With a `pool`, blocks of points run on its threads: the same distances. `bounds`, if given,
// should be bounding_box(points) (a caller that has it saves the pass); any other box gives the
// same distances, more slowly.
std::vector<double> nearest_other_distances(const PointList& points, const std::vector<std::uint32_t>& queries,
                                            parallel::ThreadPool* pool = nullptr, const Bounds* bounds = nullptr);

// The k nearest points (itself included) of every point, nearest first: row i of the
// n x min(k, n) result in `out`. `cell` should be about the k-th neighbour's distance (a larger
// one costs more distances, a smaller one more searches of two rings of cells and
// kd-tree fall-backs); ties go by index. With a `pool`, blocks of cells run on its threads: the
// same rows.
void all_nearest_neighbours(const PointList& points, std::size_t k, double cell, std::vector<std::uint32_t>& out,
                            parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::geometry
