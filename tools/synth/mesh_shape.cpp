#include "mesh_shape.hpp"

#include <filesystem>
#include <random>
#include <stdexcept>

#include "arguments.hpp"
#include "cloud_output.hpp"
#include "synth/mesh_solids.hpp"
#include "synth/mesh_visibility.hpp"
#include "synth/perturb.hpp"
#include "synth/pose.hpp"
#include "synth/visibility.hpp"

namespace cloudshape::synth_tool {
namespace {

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

bool is_mesh_shape(const std::string& shape) { return shape == "frustum"; }

void run_mesh_shape(const MeshShapeRequest& r, const std::string& output, const std::string& pcd_encoding) {
  const auto encoding = parse_pcd_encoding(pcd_encoding);
  if (r.values.size() != 3) throw std::invalid_argument("--dims: frustum needs RADIUS,TOP_RADIUS,HEIGHT");
  const double radius = r.values[0], top = r.values[1], height = r.values[2];
  if (!(radius > top && top > 0.0 && height > 0.0))
    throw std::invalid_argument("--dims: a frustum needs RADIUS > TOP_RADIUS > 0 and HEIGHT > 0");
  synth::Pose pose;
  if (r.random_pose) {
    std::seed_seq pose_seed{r.seed, std::uint64_t{0x706f7365}};
    std::mt19937_64 pose_rng(pose_seed);
    pose = synth::random_pose(pose_rng, std::max(2.0 * radius, height));
  }
  const synth::SolidMesh mesh = synth::frustum_mesh(radius, top, height, pose);
  std::mt19937_64 rng(r.seed);
  const auto sample = [&](std::size_t m) { return synth::sample_mesh_surface(mesh.vertices, mesh.triangles, m, rng); };
  PointList points;
  if (r.view) {
    const synth::MeshVisibility visibility(mesh.vertices, mesh.triangles);
    points = synth::sample_visible(sample, [&](const PointList& c) { return visibility.visible(c, *r.view); },
                                   r.points, rng);
  } else {
    points = sample(r.points);
  }
  synth::add_gaussian_noise(points, r.noise * mesh.size, rng);
  write_cloud(output, points, encoding);

  nlohmann::json axes = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) axes.push_back(vec(pose.axes.row(i).transpose()));
  nlohmann::json object = {{"shape", "frustum"},
                           {"dimensions", {{"radius", radius}, {"top_radius", top}, {"height", height}}},
                           {"pose", {{"center", vec(pose.center)}, {"axes", axes}}}};
  if (r.view) object["partial"] = true;
  nlohmann::json doc = {{"source", std::filesystem::path(output).filename().string()},
                        {"objects", nlohmann::json::array({object})},
                        {"points", points.size()},
                        {"seed", r.seed},
                        {"noise_sigma", r.noise * mesh.size},
                        {"outlier_fraction", 0.0},
                        {"outliers", 0}};
  if (r.view) doc["view"] = vec(*r.view);
  write_json(ground_truth_path(output), doc);
}

}  // namespace cloudshape::synth_tool
