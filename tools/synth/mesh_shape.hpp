// `shape` for the shapes the analytic sampler does not know (frustum): sampled on a fine mesh,
// seen exactly by ray casting, with the same ground-truth JSON as the other shapes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cloudshape::synth_tool {

struct MeshShapeRequest {
  std::string shape;           // "frustum"
  std::vector<double> values;  // INTERFACE.md order: RADIUS,TOP_RADIUS,HEIGHT
  bool random_pose = false;
  std::size_t points = 20000;
  double noise = 0.0;          // share of the solid's size
  std::optional<Eigen::Vector3d> view;
  std::uint64_t seed = 1;
};

bool is_mesh_shape(const std::string& shape);

// Writes the cloud to `output` (format by extension) and its ground truth beside it.
void run_mesh_shape(const MeshShapeRequest& request, const std::string& output, const std::string& pcd_encoding);

}  // namespace cloudshape::synth_tool
