// The accuracy run: build each condition's clouds one by one, recognise, score, report.
// Generation is inside the per-condition wall time; the pipeline dominates it.
#include "accuracy.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "accuracy_report.hpp"
#include "io/cloud_writers.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape::bench {

namespace {

SampleRow sample_row(const TestCloud& cloud, const pipeline::RecognitionResult& r) {
  const Truth& truth = cloud.truths.front();
  SampleRow row;
  row.label = truth.label;
  row.expected = truth.shape;
  row.truth_dimensions = truth.dimensions;
  row.results = r.objects.size();
  const int answer = match_results(cloud, r).front();
  if (answer >= 0) {
    const pipeline::ObjectResult& got = r.objects[answer];
    row.got = got.shape;
    row.confidence = got.confidence;
    row.partial = got.partial;
    row.got_dimensions = got.dimensions;
  }
  return row;
}

// One line per cloud: what it holds, what came out, so a failing cloud can be found by name.
void print_cloud_line(const TestCloud& cloud, const pipeline::RecognitionResult& r) {
  std::string truths, results;
  for (const auto& t : cloud.truths) truths += " " + t.shape + "{" + dimensions_text(t.dimensions) + "}";
  for (const auto& o : r.objects) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " conf=%.2f%s", o.confidence, o.partial ? " partial" : "");
    results += " " + o.shape + "{" + dimensions_text(o.dimensions) + "}" + buf +
               (o.reason.empty() ? "" : " (" + o.reason + ")");
  }
  std::fprintf(stderr, "cloud %s points=%zu %s| truth:%s | got:%s\n", cloud.source.c_str(),
               cloud.points.size(), cloud.note.empty() ? "" : (cloud.note + " ").c_str(),
               truths.c_str(), results.c_str());
}

ConditionReport run_condition(const std::string& name, const AccuracyOptions& options,
                              const config::PipelineConfig& cfg, bool progress) {
  const SuiteOptions& suite = options.suite;
  ConditionReport report;
  report.name = name;
  report.description = describe_condition(name);
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = suite_size(name, suite);
  if (name == "real" && n == 0)
    std::fprintf(stderr, "cloudshape-bench: real: no sample meshes under %s/real, skipped\n",
                 suite.shared_data_dir.c_str());
  for (std::size_t i = 0; i < n; ++i) {
    if (progress)
      std::fprintf(stderr, "\rcloudshape-bench: accuracy %-12s %4zu/%zu   ", name.c_str(), i + 1,
                   n);
    TestCloud cloud;
    try {
      cloud = make_test_cloud(name, i, suite);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "\ncloudshape-bench: %s cloud %zu skipped: %s\n", name.c_str(), i,
                   e.what());
      continue;
    }
    pipeline::RecognitionResult result;
    try {
      result = pipeline::recognize_cloud(cloud.points, cfg, cloud.source, options.pool);
    } catch (const std::exception& e) {
      // Scored as a cloud with no answer: every truth missed.
      std::fprintf(stderr, "\ncloudshape-bench: %s: recognize_cloud threw: %s\n",
                   cloud.source.c_str(), e.what());
    }
    if (!options.save_dir.empty()) {
      const std::string path = options.save_dir + "/" + cloud.source + ".pcd";
      try {
        io::write_pcd(path, cloud.points, io::PcdEncoding::binary, true);
      } catch (const std::exception& e) {
        // The cloud is still scored: a full disk costs the copy, not the measurement.
        std::fprintf(stderr, "\ncloudshape-bench: --save-clouds: %s not written: %s\n", path.c_str(), e.what());
        ++report.unsaved;
      }
    }
    if (options.per_cloud) print_cloud_line(cloud, result);
    score_cloud(cloud, result, report.tallies);
    if (name == "real") report.samples.push_back(sample_row(cloud, result));
    ++report.clouds;
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace

int run_accuracy(const AccuracyOptions& options, const config::PipelineConfig& cfg) {
  const auto& known = accuracy_conditions();
  for (const auto& c : options.conditions) {
    if (std::find(known.begin(), known.end(), c) == known.end()) {
      std::fprintf(stderr, "cloudshape-bench: --conditions: unknown condition '%s'\n", c.c_str());
      return 2;
    }
  }
  // A progress line only where someone watches: redirected logs stay readable.
  const bool progress = isatty(fileno(stderr)) != 0 && !options.per_cloud;
  std::vector<ConditionReport> reports;
  for (const auto& name : known) {
    const auto& chosen = options.conditions;
    if (!chosen.empty() && std::find(chosen.begin(), chosen.end(), name) == chosen.end()) continue;
    reports.push_back(run_condition(name, options, cfg, progress));
  }
  if (progress) std::fprintf(stderr, "\r%70s\r", "");

  if (options.json) {
    nlohmann::ordered_json settings;
    settings["count"] = options.suite.count;
    settings["seed"] = options.suite.seed;
    settings["solid_size"] = options.suite.solid_size;
    settings["points"] = {std::min<std::size_t>(2000, options.suite.max_points),
                          options.suite.max_points};
    settings["config"] = options.config_label;
    std::cout << accuracy_json(reports, settings).dump(2) << std::endl;
  } else {
    for (const auto& r : reports) std::printf("%-12s %s\n", r.name.c_str(), r.description.c_str());
    std::printf("\n");
    print_accuracy_table(reports, stdout);
  }
  std::size_t unsaved = 0;
  for (const auto& r : reports) unsaved += r.unsaved;
  if (unsaved > 0) {
    std::fprintf(stderr, "cloudshape-bench: --save-clouds: %zu clouds not written (scored all the same)\n", unsaved);
    return 1;
  }
  return 0;
}

}  // namespace cloudshape::bench
