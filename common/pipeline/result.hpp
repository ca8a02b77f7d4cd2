// What the recognizer reports for one cloud: one entry per object, with shape,
// dimensions, 6-DoF pose and confidence, plus the stage timings (INTERFACE.md).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cloudshape::pipeline {

struct KeypointCounts {
  int corner = 0;
  int edge = 0;
  int border = 0;
};

struct ObjectResult {
  std::string shape = "unknown";  // box, tetrahedron, pentagonal_prism, cone, cylinder, sphere, unknown
  double confidence = 0.0;        // 0..1: how well the solved solid explains the points
  // Ordered (name, value) pairs in the order INTERFACE.md lists them for the shape.
  std::vector<std::pair<std::string, double>> dimensions;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // row i = axes[i] of INTERFACE.md
  bool partial = false;
  KeypointCounts keypoints;
  std::string reason;  // why the shape is unknown (empty otherwise)
  // Indices into the recognized input cloud of the points this object was made from (for
  // scoring a segmentation against ground truth); not part of the JSON.
  std::vector<std::uint32_t> point_indices;
};

struct StageTimings {
  double preprocess_ms = 0.0;
  double planes_ms = 0.0;
  double keypoints_ms = 0.0;
  double classify_ms = 0.0;
  double solve_ms = 0.0;
  double total_ms = 0.0;
};

struct RecognitionResult {
  std::string source;
  std::size_t points_in = 0;
  std::size_t points_used = 0;
  double resolution = 0.0;
  std::vector<ObjectResult> objects;
  StageTimings timings;
};

}  // namespace cloudshape::pipeline
