// Stage 3 (thesis 3.1): key-points by vertex pursuit from the line extremities, climbing
// to the point locally farthest from the minimal enclosing sphere's centre.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/enclosing_sphere.hpp"
#include "geometry/kdtree.hpp"
#include "pipeline/planes.hpp"

namespace cloudshape::pipeline {

struct Keypoint {
  std::uint32_t index = 0;                   // into the cloud
  std::vector<std::uint32_t> neighbourhood;  // the key-point and its nearest neighbours
};

struct KeypointSet {
  geometry::Sphere reference;  // minimal enclosing sphere: its centre is the pursuit's reference
  std::vector<Keypoint> keypoints;
};

// Climbs from `start` to the point of its neighbourhood farthest from `centre`, until
// the farthest point is the current one. Returns the index reached.
std::uint32_t pursue_vertex(const geometry::KdTree& tree, std::uint32_t start, const Point& centre,
                            std::size_t neighbourhood, std::int64_t max_steps);

// `tree`, if given, is a search tree over `cloud` (the object's, shared by the stages).
KeypointSet find_keypoints(const PointList& cloud, const PlaneSegmentation& planes,
                           double resolution, const config::KeypointsConfig& cfg,
                           const geometry::KdTree* tree = nullptr);

}  // namespace cloudshape::pipeline
