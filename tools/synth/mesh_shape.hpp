// `shape` for the shapes the analytic sampler does not know (frustum, prism): sampled on a fine mesh,
// seen exactly by ray casting, with the same ground-truth JSON as the other shapes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cloudshape::synth_tool {

struct MeshShapeRequest {
  std::string shape;           // "frustum" or "prism"
  std::vector<double> values;  // frustum RADIUS,TOP_RADIUS,HEIGHT; prism WIDTH,HEIGHT
  std::string section;         // prism: a synth::SectionKind name, empty for one drawn by the seed
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
