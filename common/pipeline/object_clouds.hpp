// From a raw cloud to its objects: scene segmentation (common/segment) on the raw points, then
// each object preprocessed from its own raw points, at its own resolution.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"
#include "pipeline/preprocess.hpp"

namespace cloudshape::pipeline {

// One object's preprocessed points and the resolution (mean nearest-neighbour distance) they
// were gridded at (no finer than pre.noise_resolution times their noise off their surface where
// the segmentation found the pixels noisy on their own), and which raw points it was made from.
struct ObjectCloud {
  PointList points;
  double resolution = 0.0;
  std::vector<std::uint32_t> raw_indices;  // into the raw cloud
  std::shared_ptr<const geometry::KdTree> tree;  // over `points`, for every stage's neighbours
  std::uint32_t scan_lines = 0;  // in a lidar frame, the scan lines it lies on; 0 elsewhere
  // In a lidar frame, the frame's returns about it (its own among them), within
  // PreprocessConfig::free_space_reach of its angular radius: the rays that measured free space
  // beside and behind it (solve.free_space_max_share); empty elsewhere.
  PointList returns_about;
};

struct ObjectClouds {
  // What preprocessing kept, summed over the objects: points_used is their total, resolution
  // and voxel_size those of the largest object, outliers_removed the total.
  PreprocessedCloud scene;
  std::vector<ObjectCloud> objects;  // largest first
  std::optional<Point> viewpoint;    // the sensor's position, when the layout tells it
};

// segment_scene, then preprocess_cloud per object. A cloud in which segmentation finds no
// object at all (a lone plane, too few points) is preprocessed whole as one object, so that the
// recognizer can still say what it is (e.g. unknown: all points coplanar). A `pool` runs the
// segmentation's neighbour searches and the objects' preprocessing in parallel, same result.
ObjectClouds object_clouds(const PointList& raw, const GridLayout& grid, const config::PreprocessConfig& pre,
                           const config::SegmentConfig& seg, parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::pipeline
