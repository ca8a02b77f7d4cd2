#include "pipeline_harness.hpp"
#include "same_results.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "report/result_json.hpp"

namespace cloudshape::testing {
namespace fs = std::filesystem;

int domain_offset() {
  const char* v = std::getenv("CLOUDSHAPE_TEST_DOMAIN_OFFSET");
  return v == nullptr ? 0 : std::atoi(v);
}

std::string make_temp_dir(const std::string& name) {
  std::string templ = (fs::temp_directory_path() / ("cloudshape-dds-" + name + "-XXXXXX")).string();
  if (mkdtemp(templ.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return templ;
}

Pipeline::Pipeline(const std::string& name, int domain) : dir_(make_temp_dir(name)), domain_(domain + domain_offset()) {}

Pipeline::~Pipeline() {
  if (!::testing::Test::HasFailure()) fs::remove_all(dir_);
}

void Pipeline::add_common_args(const std::vector<std::string>& args) {
  common_args_.insert(common_args_.end(), args.begin(), args.end());
}

void Pipeline::start_service(const std::string& stage, std::vector<std::string> extra, const std::string& tag) {
  std::vector<std::string> argv = {kBin + "/cloudshape-" + stage, "--domain", domain()};
  argv.insert(argv.end(), common_args_.begin(), common_args_.end());
  argv.insert(argv.end(), extra.begin(), extra.end());
  const std::string log = log_path(stage + tag);
  services_.emplace_back(stage + tag, procs_.start(argv, log, log));
}

void Pipeline::start_echo(int count, const std::vector<std::string>& extra) {
  std::vector<std::string> argv = {kBin + "/cloudshape-echo", "--domain", domain(), "--count",
                                   std::to_string(count), "--timeout", std::to_string(kEchoTimeoutS)};
  argv.insert(argv.end(), common_args_.begin(), common_args_.end());
  argv.insert(argv.end(), extra.begin(), extra.end());
  echo_ = procs_.start(argv, dir_ + "/echo.jsonl", log_path("echo"));
}

ProcessResult Pipeline::inject(const std::vector<std::string>& files) {
  std::vector<std::string> argv = {kBin + "/cloudshape-inject", "--domain", domain(), "--wait",
                                   std::to_string(kStartWait.count())};
  argv.insert(argv.end(), common_args_.begin(), common_args_.end());
  argv.insert(argv.end(), files.begin(), files.end());
  return run_process(argv);
}

pid_t Pipeline::start_other(const std::vector<std::string>& argv, const std::string& out_name) {
  return procs_.start(argv, dir_ + "/" + out_name, log_path(fs::path(out_name).stem().string()));
}

std::vector<std::string> Pipeline::echo_lines() const { return lines_of(read_text(dir_ + "/echo.jsonl")); }

void Pipeline::stop_services() {
  for (const auto& [name, pid] : services_) {
    EXPECT_EQ(procs_.stop(pid, std::chrono::seconds(30)), 0)
        << name << " did not stop cleanly; log:\n" << read_text(log_path(name));
  }
  services_.clear();
}

std::vector<std::string> synthetic_clouds(const std::string& dir, int points) {
  const ProcessResult r = run_process({kBin + "/cloudshape-synth", "suite", "--out", dir, "--points",
                                       std::to_string(points), "--seed", "11", "--count", "1"});
  if (r.exit_code != 0) throw std::runtime_error("cloudshape-synth failed: " + r.err);
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".pcd") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> recognize(const std::vector<std::string>& files) {
  std::vector<std::string> argv = {kBin + "/cloudshape-recognize"};
  argv.insert(argv.end(), files.begin(), files.end());
  const ProcessResult r = run_process(argv);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return lines_of(r.out);
}

std::map<std::string, pipeline::RecognitionResult> by_source(const std::vector<std::string>& lines) {
  std::map<std::string, pipeline::RecognitionResult> results;
  for (const std::string& line : lines) {
    if (line.empty()) continue;
    pipeline::RecognitionResult r = report::result_from_json_line(line);
    EXPECT_EQ(results.count(r.source), 0u) << "two results for " << r.source;
    results[r.source] = r;
  }
  return results;
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-6 * std::max({1.0, std::abs(a), std::abs(b)}); }

void expect_same_results(const std::vector<std::string>& expected_lines, const std::vector<std::string>& actual_lines) {
  std::string report;
  for (const std::string& d : result_differences(expected_lines, actual_lines)) report += d + "\n";
  EXPECT_TRUE(report.empty()) << report;
}

}  // namespace cloudshape::testing
