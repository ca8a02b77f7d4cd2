// Process-level tests of the DDS pipeline: the five services, cloudshape-inject and
// cloudshape-echo run as real processes on a private domain (one per test, so tests can run
// in parallel), and echo must print for every file what cloudshape-recognize prints.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <tuple>
#include <string>
#include <vector>

#include "pipeline_harness.hpp"
#include "report/result_json.hpp"
#include "test_domains.hpp"

namespace cloudshape::testing {
namespace {
namespace fs = std::filesystem;

// A box and a sphere far apart in one .xyz file: two objects, two entries in one result.
std::string two_object_cloud(const std::string& dir) {
  const std::string box = dir + "/part_box.xyz", sphere = dir + "/part_sphere.xyz";
  for (const auto& [shape, dims, out] : {std::tuple<std::string, std::string, std::string>{"box", "30,20,10", box},
                                         {"sphere", "12", sphere}}) {
    const ProcessResult r = run_process({kBin + "/cloudshape-synth", "shape", "--shape", shape, "--dims", dims,
                                         "--points", "10000", "--seed", "3", "-o", out});
    if (r.exit_code != 0) throw std::runtime_error("cloudshape-synth failed: " + r.err);
  }
  const std::string both = dir + "/two_objects.xyz";
  std::ofstream out(both);
  out.precision(17);
  out << read_text(box);
  std::istringstream in(read_text(sphere));
  double x, y, z;
  while (in >> x >> y >> z) out << x + 200.0 << ' ' << y << ' ' << z << '\n';
  fs::remove(box);
  fs::remove(sphere);
  fs::remove(dir + "/part_box.json");
  fs::remove(dir + "/part_sphere.json");
  return both;
}

// CI=true (as .ci/run sets it): the shared data must be there.
bool ci_run() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && (std::string(ci) == "true" || std::string(ci) == "1");
}

// The real clouds of the equality test, each required: a missing one fails the test. Without
// the shared data folder at all the test still compares the synthetic clouds, then fails under
// CI and reports itself skipped elsewhere (`data_missing` says why).
std::vector<std::string> real_clouds(std::string& data_missing) {
  const fs::path data = CLOUDSHAPE_SHARED_DATA_DIR;
  if (!fs::is_directory(data / "real")) {
    data_missing = "shared data missing: " + (data / "real").string() + " (check out shared/ beside the repository)";
    if (ci_run()) ADD_FAILURE() << data_missing << "; CI=true requires the real clouds";
    return {};
  }
  std::vector<std::string> files;
  for (const char* f : {"pcl/milk.pcd", "pcl/mOSD_learn0_boxes.pcd", "pcl/mOSD_learn33_cylinders.pcd",
                        "spherecalib/example3_L1_S1_lidar_sphere.xyz"}) {
    const fs::path path = data / "real" / f;
    EXPECT_TRUE(fs::is_regular_file(path)) << "real cloud missing: " << path;
    if (fs::is_regular_file(path)) files.push_back(path.string());
  }
  return files;
}

int count_matches(const std::string& text, const std::string& pattern) {
  const std::regex re(pattern);
  return static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

TEST(DdsPipeline, EchoPrintsWhatRecognizePrints) {
  Pipeline p("equivalence", domains::pipeline_equivalence);
  std::vector<std::string> files = synthetic_clouds(p.dir() + "/clouds", 20000);
  ASSERT_FALSE(files.empty()) << "cloudshape-synth suite wrote no cloud";
  std::string data_missing;
  for (const std::string& f : real_clouds(data_missing)) files.push_back(f);
  files.push_back(two_object_cloud(p.dir()));
  std::printf("comparing %zu clouds:\n", files.size());
  for (const std::string& f : files) std::printf("  %s\n", f.c_str());
  const std::vector<std::string> expected = recognize(files);
  ASSERT_EQ(expected.size(), files.size());
  ASSERT_EQ(report::result_from_json_line(expected.back()).objects.size(), 2u) << expected.back();

  const std::string bad = p.dir() + "/broken.pcd";
  { std::ofstream(bad) << "this is not a point cloud\n"; }
  std::vector<std::string> injected = files;
  injected.insert(injected.begin() + 1, bad);

  p.start_echo(static_cast<int>(files.size()));
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject(injected);
  EXPECT_EQ(inj.exit_code, 2) << "a bad file must give exit status 2; stderr:\n" << inj.err;
  EXPECT_EQ(count_matches(inj.err, "broken\\.pcd"), 1) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << "echo did not print every result; its log:\n" << read_text(p.log_path("echo"));
  expect_same_results(expected, p.echo_lines());
  p.stop_services();
  if (!data_missing.empty()) GTEST_SKIP() << "compared only the synthetic clouds: " << data_missing;
}

TEST(DdsPipeline, TwoKeypointsReplicasSplitTheWork) {
  Pipeline p("replicas", domains::pipeline_replicas);
  const std::vector<std::string> files = synthetic_clouds(p.dir() + "/clouds", 8000);
  const std::vector<std::string> expected = recognize(files);

  p.start_echo(static_cast<int>(files.size()));
  p.start_service("solver");
  p.start_service("classifier");
  p.start_service("keypoints", {"--lane", "0", "--lanes", "2"}, "0");
  p.start_service("keypoints", {"--lane", "1", "--lanes", "2"}, "1");
  // planes waits for both replicas, so no cloud is published before lane 1 listens.
  p.start_service("planes", {"--subscribers", "2"});
  p.start_service("ingest");
  const ProcessResult inj = p.inject(files);
  ASSERT_EQ(inj.exit_code, 0) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  expect_same_results(expected, p.echo_lines());
  p.stop_services();
  // Cloud ids 0..5: each replica handled exactly its half, none twice.
  const int lane0 = count_matches(read_text(p.log_path("keypoints0")), "cloud [0-9]+ .*: done");
  const int lane1 = count_matches(read_text(p.log_path("keypoints1")), "cloud [0-9]+ .*: done");
  EXPECT_EQ(lane0 + lane1, static_cast<int>(files.size()));
  EXPECT_EQ(lane0, static_cast<int>((files.size() + 1) / 2));
  EXPECT_EQ(lane1, static_cast<int>(files.size() / 2));
}

TEST(DdsPipeline, AFailingStageStillGivesOneResult) {
  Pipeline p("error", domains::pipeline_failing_stage);
  const std::vector<std::string> files = synthetic_clouds(p.dir() + "/clouds", 4000);
  p.start_echo(static_cast<int>(files.size()));
  for (const std::string& s : kStages) {
    // An ingest that refuses every cloud: its error must travel down to the solver.
    p.start_service(s, s == "ingest" ? std::vector<std::string>{"--max-points", "100"} : std::vector<std::string>{});
  }
  const ProcessResult inj = p.inject(files);
  ASSERT_EQ(inj.exit_code, 0) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  const auto results = by_source(p.echo_lines());
  ASSERT_EQ(results.size(), files.size());
  for (const auto& [source, r] : results) {
    ASSERT_EQ(r.objects.size(), 1u);
    EXPECT_EQ(r.objects[0].shape, "unknown");
    EXPECT_NE(r.objects[0].reason.find("ingest"), std::string::npos) << r.objects[0].reason;
    EXPECT_NE(r.objects[0].reason.find("more than input.max_points 100"), std::string::npos) << r.objects[0].reason;
  }
  p.stop_services();
}

// The lines of cloudshape-cyclone-echo and examples/subscribe_results.cpp, one per object
// (source \t i/n \t shape \t name=value,... \t reason), against recognize's results.
void expect_object_lines_match(const std::map<std::string, pipeline::RecognitionResult>& expected,
                               const std::vector<std::string>& lines, std::size_t count) {
  ASSERT_EQ(lines.size(), count);
  for (const std::string& line : lines) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, '\t');) f.push_back(x);
    ASSERT_GE(f.size(), 4u) << line;
    SCOPED_TRACE(line);
    ASSERT_EQ(expected.count(f[0]), 1u);
    const pipeline::ObjectResult& e = expected.at(f[0]).objects.at(0);
    EXPECT_EQ(f[2], e.shape);
    for (const auto& [name, value] : e.dimensions) {
      std::stringstream d(f[3]);
      bool found = false;
      for (std::string kv; std::getline(d, kv, ',');) {
        const auto eq = kv.find('=');
        if (kv.substr(0, eq) == name) {
          found = true;
          EXPECT_TRUE(close(std::stod(kv.substr(eq + 1)), value)) << name;
        }
      }
      EXPECT_TRUE(found) << name;
    }
  }
}

// Cross-vendor: a Cyclone DDS program, built from the same IDL with idlc, reads the results.
TEST(DdsPipeline, CycloneDdsReadsTheResults) {
#ifndef CLOUDSHAPE_CYCLONE_ECHO
  GTEST_SKIP() << "cloudshape-cyclone-echo not built (needs cyclonedds-dev, cyclonedds-tools)";
#else
  Pipeline p("cyclone", domains::pipeline_cyclone);
  const std::vector<std::string> files = synthetic_clouds(p.dir() + "/clouds", 8000);
  const auto expected = by_source(recognize(files));
  // Cyclone on loopback with unicast discovery, like the Fast DDS side (config/qos.xml).
  setenv("CYCLONEDDS_URI", "file://" CLOUDSHAPE_SOURCE_DIR "/config/cyclonedds_localhost.xml", 1);
  const pid_t reader = p.start_other({CLOUDSHAPE_CYCLONE_ECHO, "--domain", p.domain(), "--count",
                                      std::to_string(files.size()), "--timeout", std::to_string(kEchoTimeoutS)},
                                     "cyclone.txt");
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject(files);
  ASSERT_EQ(inj.exit_code, 0) << inj.err;
  ASSERT_EQ(p.wait_other(reader), 0) << read_text(p.log_path("cyclone"));
  expect_object_lines_match(expected, lines_of(read_text(p.dir() + "/cyclone.txt")), files.size());
  p.stop_services();
#endif
}

// docs/dds.md's Fast DDS subscriber (examples/subscribe_results.cpp) reads the results.
TEST(DdsPipeline, ExampleSubscriberReadsTheResults) {
  Pipeline p("example", domains::pipeline_example_subscriber);
  const std::vector<std::string> files = synthetic_clouds(p.dir() + "/clouds", 4000);
  const auto expected = by_source(recognize(files));
  const pid_t reader = p.start_other({kBin + "/cloudshape-example-subscribe", CLOUDSHAPE_SOURCE_DIR "/config/qos.xml",
                                      p.domain(), std::to_string(files.size())},
                                     "example.txt");
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject(files);
  ASSERT_EQ(inj.exit_code, 0) << inj.err;
  ASSERT_EQ(p.wait_other(reader), 0) << read_text(p.log_path("example"));
  expect_object_lines_match(expected, lines_of(read_text(p.dir() + "/example.txt")), files.size());
  p.stop_services();
}

}  // namespace
}  // namespace cloudshape::testing
