// Output of cloudshape-bench --accuracy: the per condition x shape table and its JSON twin.
// Pure formatting over finished tallies; nothing here runs the pipeline.
#pragma once

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "accuracy_score.hpp"

namespace cloudshape::bench {

// One real sample's answer, listed object by object below the table.
struct SampleRow {
  std::string label;
  std::string expected;
  std::string got = "none";
  double confidence = 0.0;
  bool partial = false;
  std::vector<std::pair<std::string, double>> truth_dimensions;
  std::vector<std::pair<std::string, double>> got_dimensions;
  std::size_t results = 0;  // objects the recognizer reported for the cloud
};

struct ConditionReport {
  std::string name;
  std::string description;
  std::size_t clouds = 0;
  double seconds = 0.0;                  // wall time: generation plus recognition
  std::map<std::string, Tally> tallies;  // by truth shape
  std::vector<SampleRow> samples;        // real condition only
  std::size_t unsaved = 0;               // --save-clouds copies that could not be written
};

void print_accuracy_table(const std::vector<ConditionReport>& reports, std::FILE* out);

// "length 30, width 20" (4 significant digits); "-" when there is none.
std::string dimensions_text(const std::vector<std::pair<std::string, double>>& dimensions);

nlohmann::ordered_json accuracy_json(const std::vector<ConditionReport>& reports,
                                     const nlohmann::ordered_json& settings);

}  // namespace cloudshape::bench
