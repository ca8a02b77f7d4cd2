// Shared by the tests of the shapes beyond the six and of the negatives: a mesh solid sampled
// (optionally noisy) and recognised with the shipped configuration.
#pragma once

#include <cstdint>
#include <string>

#include "config/pipeline_config.hpp"
#include "pipeline/result.hpp"
#include "synth/mesh_solids.hpp"

namespace cloudshape::newshapes {

// `points` area-uniform points of the mesh, Gaussian noise sigma `noise` x its size.
PointList sample(const synth::SolidMesh& mesh, std::size_t points, double noise, std::uint64_t seed);

// What a camera at `camera` sees of the mesh: `points` visible points (exact ray casting), the
// same noise.
PointList sample_view(const synth::SolidMesh& mesh, std::size_t points, double noise, const Eigen::Vector3d& camera,
                      std::uint64_t seed);

// recognize_cloud with config/pipeline.yaml (or `cfg`); the cloud must give exactly one object.
pipeline::ObjectResult recognise_one(const PointList& cloud);
pipeline::ObjectResult recognise_one(const PointList& cloud, const config::PipelineConfig& cfg);

// config/pipeline.yaml as shipped.
config::PipelineConfig shipped_config();

// A frustum's proportions: the larger end's radius, the smaller end's, the height.
struct FrustumCase {
  double radius, top_radius, height;
};

// The object's dimension `name`; a test failure (and 0) when it has none.
double dimension(const pipeline::ObjectResult& o, const std::string& name);

}  // namespace cloudshape::newshapes
