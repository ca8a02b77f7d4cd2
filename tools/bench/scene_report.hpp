// cloudshape-bench --scenes: per-category tallies of scored scenes, rendered as a table or JSON.
// Pure functions of the scored runs, so tests can check the sums without running recognition.
#pragma once

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "scene_score.hpp"

namespace cloudshape::bench {

// One scene, recognised and scored.
struct SceneRun {
  std::string file;  // the file name, without the directory
  std::string category;
  std::string truth;       // the truth file or sidecar its expected shapes came from
  std::size_t points = 0;  // finite points given to recognize_cloud
  bool organized = false;
  struct Report {
    std::string shape;
    double confidence = 0.0;
  };
  std::vector<Report> reported;  // per reported object, in its order
  SceneScore score;
  double wall_ms = 0.0;   // wall clock around recognize_cloud
  double total_ms = 0.0;  // the result's own timings.total_ms
  double cpu_ms = 0.0;    // process CPU time around recognize_cloud: steady on a shared machine
};

struct SceneTally {
  int scenes = 0;
  int objects = 0;
  int right = 0;
  int wrong_shape = 0;
  int missed = 0;
  int false_objects = 0;
  int duplicates = 0;
  int table = 0;
  std::vector<double> ious;  // per matched object with point indices
  std::vector<double> wall_ms;
  std::vector<double> total_ms;
  std::vector<double> cpu_ms;
  std::map<std::string, int> wrong_as;  // reported shape of wrong-shape objects -> count
};

// Rows in `category_order` (then any other category, by name), then "all".
std::vector<std::pair<std::string, SceneTally>> tally_scenes(
    const std::vector<SceneRun>& runs, const std::vector<std::string>& category_order);

// Median (mean of the middle two on an even count) and maximum; 0 for an empty set.
double median_of(std::vector<double> v);
double max_of(const std::vector<double>& v);

void print_scene_table(const std::vector<std::pair<std::string, SceneTally>>& rows, std::FILE* out);
// One line per scene: what was labelled, what came out, how it was counted.
void print_scene_lines(const std::vector<SceneRun>& runs, std::FILE* out);

nlohmann::ordered_json scenes_json(const std::vector<SceneRun>& runs,
                                   const std::vector<std::pair<std::string, SceneTally>>& rows,
                                   const nlohmann::ordered_json& settings);

}  // namespace cloudshape::bench
