#include "new_shapes_support.hpp"

#include <gtest/gtest.h>

#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"
#include "synth/mesh_visibility.hpp"
#include "synth/visibility.hpp"

namespace cloudshape::newshapes {

PointList sample(const synth::SolidMesh& mesh, std::size_t points, double noise, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  PointList cloud = synth::sample_mesh_surface(mesh.vertices, mesh.triangles, points, rng);
  std::normal_distribution<double> n(0.0, noise * mesh.size);
  if (noise > 0.0)
    for (Point& p : cloud) p += Eigen::Vector3d(n(rng), n(rng), n(rng));
  return cloud;
}

PointList sample_view(const synth::SolidMesh& mesh, std::size_t points, double noise, const Eigen::Vector3d& camera,
                      std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const synth::MeshVisibility visibility(mesh.vertices, mesh.triangles);
  PointList cloud = synth::sample_visible(
      [&](std::size_t m) { return synth::sample_mesh_surface(mesh.vertices, mesh.triangles, m, rng); },
      [&](const PointList& c) { return visibility.visible(c, camera); }, points, rng);
  std::normal_distribution<double> n(0.0, noise * mesh.size);
  if (noise > 0.0)
    for (Point& p : cloud) p += Eigen::Vector3d(n(rng), n(rng), n(rng));
  return cloud;
}

config::PipelineConfig shipped_config() {
  return config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
}

pipeline::ObjectResult recognise_one(const PointList& cloud) {
  return recognise_one(cloud, shipped_config());
}

pipeline::ObjectResult recognise_one(const PointList& cloud, const config::PipelineConfig& cfg) {
  const pipeline::RecognitionResult r = pipeline::recognize_cloud(cloud, cfg, "test");
  EXPECT_EQ(r.objects.size(), 1u);
  return r.objects.empty() ? pipeline::ObjectResult{} : r.objects.front();
}

double dimension(const pipeline::ObjectResult& o, const std::string& name) {
  for (const auto& [n, v] : o.dimensions)
    if (n == name) return v;
  ADD_FAILURE() << "no dimension " << name;
  return 0.0;
}

}  // namespace cloudshape::newshapes
