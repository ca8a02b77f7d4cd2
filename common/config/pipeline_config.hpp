// Every tunable of the recognition pipeline (input limits, one plain struct per stage, the ROS 2
// topics and markers), and the loader that fills them from config/pipeline.yaml (unknown keys are rejected).
#pragma once

#include <stdexcept>
#include <string>

#include "config/ros2_config.hpp"
#include "config/stage_configs.hpp"

namespace cloudshape::config {

struct PipelineConfig {
  InputConfig input;
  ExecutionConfig execution;
  PreprocessConfig preprocess;
  SegmentConfig segment;
  PlanesConfig planes;
  KeypointsConfig keypoints;
  ClassifyConfig classify;
  SolveConfig solve;
  Ros2Config ros2;
};

// A configuration file that cannot be used: names the file, the key and the problem.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Loads `path`; keys that are absent keep their defaults. Throws ConfigError on an
// unknown section or key, a value of the wrong type, or a value out of range.
PipelineConfig load_pipeline_config(const std::string& path);

// The pipeline.yaml shipped with the sources, found next to the executable's build
// tree or at the compiled-in source path; empty when neither exists.
std::string default_pipeline_config_path();

}  // namespace cloudshape::config
