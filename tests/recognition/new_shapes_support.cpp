#include "new_shapes_support.hpp"

#include <gtest/gtest.h>

#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape::newshapes {

PointList sample(const synth::SolidMesh& mesh, std::size_t points, double noise, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  PointList cloud = synth::sample_mesh_surface(mesh.vertices, mesh.triangles, points, rng);
  std::normal_distribution<double> n(0.0, noise * mesh.size);
  if (noise > 0.0)
    for (Point& p : cloud) p += Eigen::Vector3d(n(rng), n(rng), n(rng));
  return cloud;
}

pipeline::ObjectResult recognise_one(const PointList& cloud) {
  const config::PipelineConfig cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const pipeline::RecognitionResult r = pipeline::recognize_cloud(cloud, cfg, "test");
  EXPECT_EQ(r.objects.size(), 1u);
  return r.objects.empty() ? pipeline::ObjectResult{} : r.objects.front();
}

}  // namespace cloudshape::newshapes
