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

// The oriented bounding box of an object's own points (what was seen): rows of `axes` are
// unit directions, right-handed, with size[0] >= size[1] >= size[2] the full edge lengths.
struct Extent {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};

struct ObjectResult {
  // box, tetrahedron, pentagonal_prism, prism, cone, frustum, cylinder, sphere, unknown
  std::string shape = "unknown";
  double confidence = 0.0;        // 0..1: how well the solved solid explains the points
  // Ordered (name, value) pairs in the order INTERFACE.md lists them for the shape.
  std::vector<std::pair<std::string, double>> dimensions;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // row i = axes[i] of INTERFACE.md
  bool partial = false;
  KeypointCounts keypoints;
  std::string reason;  // why the shape is unknown (empty otherwise)
  Extent extent;       // every object, unknown ones too
  // prism only: the cross-section, counter-clockwise in the (axes[1], axes[2]) plane about center.
  std::vector<Eigen::Vector2d> polygon;
  // tetrahedron only: its four corners, and whether its six edges are equal (solve.regular_tolerance).
  std::vector<Eigen::Vector3d> vertices;
  bool regular = false;
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
