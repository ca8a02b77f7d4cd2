#include "mesh_shape.hpp"

#include <algorithm>
#include <filesystem>
#include <random>
#include <stdexcept>

#include "arguments.hpp"
#include "cloud_output.hpp"
#include "synth/mesh_solids.hpp"
#include "synth/prism_section.hpp"
#include "synth/mesh_visibility.hpp"
#include "synth/perturb.hpp"
#include "synth/pose.hpp"
#include "synth/visibility.hpp"

namespace cloudshape::synth_tool {
namespace {

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

bool is_mesh_shape(const std::string& shape) { return shape == "frustum" || shape == "prism"; }

namespace {

struct MeshSolid {
  synth::SolidMesh mesh;
  nlohmann::json object;
};

nlohmann::json pose_json(const synth::Pose& pose) {
  nlohmann::json axes = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) axes.push_back(vec(pose.axes.row(i).transpose()));
  return {{"center", vec(pose.center)}, {"axes", axes}};
}

synth::Pose drawn_pose(const MeshShapeRequest& r, double size) {
  if (!r.random_pose) return {};
  std::seed_seq pose_seed{r.seed, std::uint64_t{0x706f7365}};
  std::mt19937_64 pose_rng(pose_seed);
  return synth::random_pose(pose_rng, size);
}

MeshSolid frustum(const MeshShapeRequest& r) {
  if (r.values.size() != 3) throw std::invalid_argument("--dims: frustum needs RADIUS,TOP_RADIUS,HEIGHT");
  const double radius = r.values[0], top = r.values[1], height = r.values[2];
  if (!(radius > top && top > 0.0 && height > 0.0))
    throw std::invalid_argument("--dims: a frustum needs RADIUS > TOP_RADIUS > 0 and HEIGHT > 0");
  const synth::Pose pose = drawn_pose(r, std::max(2.0 * radius, height));
  return {synth::frustum_mesh(radius, top, height, pose),
          {{"shape", "frustum"},
           {"dimensions", {{"radius", radius}, {"top_radius", top}, {"height", height}}},
           {"pose", pose_json(pose)}}};
}

// A prism: its cross-section of the kind asked (else one drawn by the seed), WIDTH its largest
// extent; the ground truth carries the polygon as the recognizer reports it.
MeshSolid prism(const MeshShapeRequest& r) {
  if (r.values.size() != 2 || !(r.values[0] > 0.0) || !(r.values[1] > 0.0))
    throw std::invalid_argument("--dims: prism needs WIDTH,HEIGHT, both > 0");
  std::seed_seq section_seed{r.seed, std::uint64_t{0x7365637469}};
  std::mt19937_64 rng(section_seed);
  const auto& kinds = synth::all_section_kinds();
  auto kind = kinds[std::uniform_int_distribution<std::size_t>(0, kinds.size() - 1)(rng)];
  if (!r.section.empty()) {
    const auto it = std::find_if(kinds.begin(), kinds.end(), [&](auto k) { return synth::to_string(k) == r.section; });
    if (it == kinds.end()) throw std::invalid_argument("--section: unknown cross-section '" + r.section + "'");
    kind = *it;
  }
  const synth::PrismSection section = synth::random_section(kind, rng);
  geometry::Polygon2 polygon = section.polygon;
  for (auto& p : polygon) p *= r.values[0];
  const double height = r.values[1];
  const synth::Pose pose = drawn_pose(r, std::max(r.values[0], height));
  nlohmann::json dims = {{"height", height}, {"sides", polygon.size()}};
  if (section.regular) dims["side"] = geometry::perimeter(polygon) / static_cast<double>(polygon.size());
  nlohmann::json poly = nlohmann::json::array();
  for (const auto& p : polygon) poly.push_back({p.x(), p.y()});
  return {synth::prism_mesh(polygon, height, pose),
          {{"shape", "prism"}, {"section", synth::to_string(kind)}, {"dimensions", dims},
           {"polygon", poly}, {"pose", pose_json(pose)}}};
}

}  // namespace

void run_mesh_shape(const MeshShapeRequest& r, const std::string& output, const std::string& pcd_encoding) {
  const auto encoding = parse_pcd_encoding(pcd_encoding);
  MeshSolid solid = r.shape == "prism" ? prism(r) : frustum(r);
  const synth::SolidMesh& mesh = solid.mesh;
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

  nlohmann::json object = solid.object;
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
