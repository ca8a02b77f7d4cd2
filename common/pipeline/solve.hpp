// Stage 5 (thesis 3.3): dimensions and 6-DoF pose of the classified solid, every
// candidate verified against the points; confidence from how well it explains them.
#pragma once

#include <optional>
#include <vector>

#include "config/stage_configs.hpp"
#include "parallel/thread_pool.hpp"
#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/result.hpp"

namespace cloudshape::pipeline {

// Fits each candidate of the classification, measures the share of points within
// cfg.inlier_distance resolutions of its surface, and reports the class the key-points
// chose unless another solid explains clearly more. `unknown` with a reason when none
// explains at least cfg.min_inlier_fraction of the points.
// `tree`, if given, is a search tree over `cloud` (the object's, shared by the stages). With the
// sensor's `viewpoint` known (organized clouds), a sphere seen from its hollow side is a
// container's inside (container.hpp). `objects_in_cloud`: how many objects the cloud this one
// came from held; only an object alone, with no viewpoint, may show a notch on its cap's border
// alone (solid_prism.cpp: nothing beside it could have hidden that stretch of the cap).
// `scan_lines`: the lidar scan lines the object lies on (0: not a lidar frame). Two lines are two
// curves across the object: they fix a sphere (two circles of it) and no other solid, whose
// extent between and beyond them they leave open; on two, only a sphere is tried. There
// `returns_about` (ObjectCloud::returns_about: the frame's returns about the object) weighs the
// solid chosen against the free space the sensor measured (cfg.free_space_max_share). A `pool`
// fits the candidates, and searches the extent from its starts, side by side: the same result.
ObjectResult solve_object(const PointList& cloud, const PlaneSegmentation& planes,
                          const KeypointSet& keypoints, const Classification& classification,
                          double resolution, const config::SolveConfig& cfg,
                          const geometry::KdTree* tree = nullptr,
                          const std::optional<Point>& viewpoint = std::nullopt,
                          std::size_t objects_in_cloud = 1, std::uint32_t scan_lines = 0,
                          parallel::ThreadPool* pool = nullptr,
                          const PointList* returns_about = nullptr);

namespace detail {
// Whether a frustum's fit can change which solid solve_object chooses among the others, given the
// shares of the points the others explain (`explained`: the admissible ones) and
// cfg.preferred_margin: where it cannot, solve_object does not fit it.
bool frustum_may_matter(const std::vector<double>& explained, double margin);
}  // namespace detail

}  // namespace cloudshape::pipeline
