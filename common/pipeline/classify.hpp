// Stage 4 (thesis 3.2-3.3): each key-point typed corner / edge / border from the
// covariance of its neighbourhood; the sphere test; the shape class from Table 3.1.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "config/stage_configs.hpp"
#include "pipeline/face_outline.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/result.hpp"
#include "pipeline/shape.hpp"

namespace cloudshape::pipeline {

enum class KeypointType { corner, edge, border };

struct TypedKeypoint {
  std::uint32_t index = 0;
  KeypointType type = KeypointType::edge;
  double curvature = 0.0;    // surface variation of the neighbourhood (thesis eq. 3.5)
  double gap_degrees = 0.0;  // largest angular gap of the neighbourhood projected on the e1 plane
};

struct Classification {
  std::vector<TypedKeypoint> keypoints;
  KeypointCounts counts;
  Shape shape = Shape::unknown;  // the class from the key-points (Table 3.1) or the sphere test
  // Hypotheses for the solver, most likely first; empty when the cloud holds no solid.
  std::vector<Shape> candidates;
  std::string reason;            // why there is no solid (degenerate cloud)
  double face_fraction = 0.0;    // share of the points lying on true flat faces
  bool sphere_test = false;
  // Outlines of the large faces in their own planes. A circle is a lid or a bottom (only solids
  // of revolution have one), a rectangle a polyhedron's face; when the faces disagree neither counts.
  std::optional<std::size_t> cap_plane;  // index in planes.planes of the largest circular face
  FaceOutline cap_outline;
  bool rectangular_face = false;
};

// Types one key-point from its neighbourhood (thesis 3.2.2-3.2.3).
TypedKeypoint type_keypoint(const PointList& cloud, const Keypoint& keypoint,
                            const config::ClassifyConfig& cfg);

// Table 3.1: corners 0 -> cylinder (sphere by the sphere test), 1 -> cone,
// 4 -> tetrahedron, 8 -> box, 10 -> pentagonal prism; anything else -> unknown.
Shape shape_from_keypoints(const KeypointCounts& counts);

Classification classify_cloud(const PointList& cloud, const PlaneSegmentation& planes,
                              const KeypointSet& keypoints, double resolution,
                              const config::ClassifyConfig& cfg);

}  // namespace cloudshape::pipeline
