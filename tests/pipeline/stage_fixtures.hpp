// Clouds with known answers for the stage tests: an exact box, cylinder, cone, sphere,
// sampled by the synth library, run through the stages up to the one under test.
#pragma once

#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/preprocess.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape::pipeline::testing {

struct StagedCloud {
  synth::SolidSpec spec;
  PreprocessedCloud pre;
  PlaneSegmentation planes;
  KeypointSet keypoints;
  Classification classification;
};

inline synth::Pose tilted_pose() {
  synth::Pose pose;
  pose.center = Eigen::Vector3d(0.4, -0.2, 1.5);
  pose.axes = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  return pose;
}

inline StagedCloud stage(synth::ShapeKind kind, const std::vector<double>& dims,
                         std::size_t points = 20000, std::uint64_t seed = 1) {
  const config::PipelineConfig cfg;
  StagedCloud s;
  s.spec = synth::make_solid(kind, dims, tilted_pose());
  std::mt19937_64 rng(seed);
  s.pre = preprocess_cloud(synth::sample_solid_surface(s.spec, points, rng), cfg.preprocess);
  s.planes = segment_planes(s.pre.points, s.pre.resolution, cfg.planes);
  s.keypoints = find_keypoints(s.pre.points, s.planes, s.pre.resolution, cfg.keypoints);
  s.classification = classify_cloud(s.pre.points, s.planes, s.keypoints, s.pre.resolution, cfg.classify);
  return s;
}

inline int face_count(const PlaneSegmentation& planes) {
  int n = 0;
  for (const auto& p : planes.planes) n += p.is_face;
  return n;
}

}  // namespace cloudshape::pipeline::testing
