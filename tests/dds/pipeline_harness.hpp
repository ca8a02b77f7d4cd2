// The process-level DDS test harness: a Pipeline of real service, echo and inject processes on
// one private domain, sample clouds, and the "same results as cloudshape-recognize" check.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "../tools/process.hpp"
#include "background.hpp"
#include "pipeline/result.hpp"

namespace cloudshape::testing {

inline const std::string kBin = CLOUDSHAPE_BIN_DIR;
inline const std::vector<std::string> kStages = {"ingest", "planes", "keypoints", "classifier", "solver"};

// Generous everywhere: these run on a loaded 2-core machine next to a parallel build.
inline constexpr std::chrono::seconds kStartWait{60};
inline constexpr int kEchoTimeoutS = 180;

// CLOUDSHAPE_TEST_DOMAIN_OFFSET shifts every test's domain, so that two checkouts can run
// their DDS tests on one machine at the same time without hearing each other.
int domain_offset();

std::string make_temp_dir(const std::string& name);

// The services, echo and inject of one test on one domain; everything is stopped at the end.
class Pipeline {
 public:
  Pipeline(const std::string& name, int domain);
  ~Pipeline();

  const std::string& dir() const { return dir_; }
  std::string domain() const { return std::to_string(domain_); }

  // From now on the services, echo and inject it starts get these arguments too
  // (e.g. --security DIR).
  void add_common_args(const std::vector<std::string>& args);

  void start_service(const std::string& stage, std::vector<std::string> extra = {}, const std::string& tag = "");
  void start_echo(int count, const std::vector<std::string>& extra = {});
  ProcessResult inject(const std::vector<std::string>& files);

  // Another program (stdout to dir/out_name, stderr to its log).
  pid_t start_other(const std::vector<std::string>& argv, const std::string& out_name);
  int wait_other(pid_t pid) { return wait_other(pid, std::chrono::seconds(kEchoTimeoutS + 30)); }
  int wait_other(pid_t pid, std::chrono::seconds timeout) { return procs_.wait(pid, timeout); }
  int stop_other(pid_t pid) { return procs_.stop(pid, std::chrono::seconds(30)); }

  // Echo's exit status once it printed its --count results (or timed out).
  int wait_echo() { return procs_.wait(echo_, std::chrono::seconds(kEchoTimeoutS + 30)); }
  std::vector<std::string> echo_lines() const;

  // SIGTERM to every service: each must stop cleanly with status 0.
  void stop_services();

  std::string log_path(const std::string& name) const { return dir_ + "/" + name + ".log"; }

 private:
  std::string dir_;
  int domain_;
  std::vector<std::string> common_args_;
  Background procs_;
  std::vector<std::pair<std::string, pid_t>> services_;
  pid_t echo_ = -1;
};

// One cloud per shape from cloudshape-synth suite (fixed seed), sorted by name.
std::vector<std::string> synthetic_clouds(const std::string& dir, int points);

// cloudshape-recognize's JSON lines for the files (expects exit status 0).
std::vector<std::string> recognize(const std::vector<std::string>& files);

std::map<std::string, pipeline::RecognitionResult> by_source(const std::vector<std::string>& lines);

// Equal within 1e-6 relative (absolute below 1): for numbers other programs print as text.
bool close(double a, double b);

// The acceptance criterion (same_results.hpp): every field of every object, axes included.
void expect_same_results(const std::vector<std::string>& expected_lines, const std::vector<std::string>& actual_lines);

}  // namespace cloudshape::testing
