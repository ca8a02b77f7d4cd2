// cloudshape-bench --accuracy: recognition rate and dimension/pose errors per condition and
// shape, on fixed-seed synthetic suites and the real sample meshes.
#pragma once

#include <string>
#include <vector>

#include "accuracy_suites.hpp"
#include "config/pipeline_config.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::bench {

struct AccuracyOptions {
  SuiteOptions suite;
  std::vector<std::string> conditions;  // empty: all of accuracy_conditions()
  bool json = false;
  bool per_cloud = false;  // one line per cloud on stderr: truths, results, view note
  std::string save_dir;   // when set, every cloud is also written there as <source>.pcd
  std::string config_label;  // what --json reports as the configuration used
  parallel::ThreadPool* pool = nullptr;  // --threads: recognize_cloud's threads (same answers)
};

// Runs the selected conditions and prints the table (or JSON) on stdout, progress on stderr.
// Returns the exit status: 0, or 2 for an unknown condition name.
int run_accuracy(const AccuracyOptions& options, const config::PipelineConfig& cfg);

}  // namespace cloudshape::bench
