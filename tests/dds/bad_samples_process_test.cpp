// Process-level: the five services receive raw-cloud samples that no file reader would make (NaN
// points, a length that is not x y z triples, zero points, more points than input.max_points, a
// sensor's object_count 0, a pixel outside its grid), clouds with no solid in them and a sample
// that does not deserialize; every one ends in exactly one result line from cloudshape-echo that
// names the input (source, and the cloud id) and the problem (reason).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <sstream>

#include "corrupt_sample.hpp"
#include "dds/convert.hpp"
#include "dds/endpoints.hpp"
#include "dds/topics.hpp"
#include "pipeline_harness.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"
#include "test_domains.hpp"

namespace cloudshape::testing {
namespace {
namespace fs = std::filesystem;
using namespace std::chrono_literals;
using ::testing::HasSubstr;

constexpr int kMaxPoints = 5000;   // input.max_points of this test's configuration
constexpr std::uint64_t kUndecodableId = 4242;  // the id of the sample that does not deserialize

// The raw-cloud topic with a type that breaks every sample it writes (corrupt_sample.hpp).
const dds::TopicSpec<msg::RawCloud, CorruptingPubSubType<msg::RawCloud, msg::RawCloudPubSubType>>
    kCorruptRawCloud{dds::topics::raw_cloud.name};

PointList solid_points(synth::ShapeKind kind, std::size_t n) {
  std::mt19937_64 rng(21);
  return synth::sample_solid_surface(synth::random_solid(kind, rng, 30.0), n, rng);
}

struct Sample {
  std::string source;
  std::vector<double> xyz;
  std::uint32_t object_count = 1;
  std::uint32_t width = 0, height = 0;  // an organized sample's layout
  std::vector<std::uint32_t> pixel = {};
};

std::vector<Sample> samples() {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  std::vector<Sample> s;
  std::vector<double> box = dds::to_xyz(solid_points(synth::ShapeKind::box, 4000));
  std::vector<double> some_nan = box;
  some_nan[0] = nan;
  some_nan[4] = inf;
  s.push_back({"some_nan", some_nan});
  s.push_back({"all_nan", std::vector<double>(300, nan)});
  s.push_back({"ten_values", std::vector<double>(10, 1.0)});
  s.push_back({"zero_points", {}});
  s.push_back({"over_limit", dds::to_xyz(solid_points(synth::ShapeKind::box, kMaxPoints + 1))});
  s.push_back({"object_count_zero", box, 0});
  s.push_back({"one_point", {1, 2, 3}});
  s.push_back({"three_points", {0, 0, 0, 1, 0, 0, 0, 1, 0}});
  std::vector<double> repeated, line, plane;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 3000; ++i) {
    repeated.insert(repeated.end(), {4.0, 5.0, 6.0});
    line.insert(line.end(), {0.01 * i, 0.02 * i, -0.03 * i});
    const double a = u(rng), b = u(rng);
    plane.insert(plane.end(), {a, b, 0.5 * a - 0.25 * b + 2.0});
  }
  s.push_back({"repeated_point", repeated});
  s.push_back({"collinear", line});
  s.push_back({"coplanar", plane});
  Sample beyond_grid{"pixel_beyond_grid", box, 1, 100, 50, {}};
  for (std::uint32_t i = 0; i < 4000; ++i) beyond_grid.pixel.push_back(i + 1001);  // the last is 5000
  s.push_back(beyond_grid);
  return s;
}

// Cloud id by source, from the latency lines of cloudshape-echo --latency:
// "cloudshape-echo: latency_ms 12.3 cloud ID SOURCE received_ns NS".
std::map<std::string, std::uint64_t> echoed_ids(const std::string& echo_log) {
  std::map<std::string, std::uint64_t> ids;
  std::istringstream lines(echo_log);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string tool, latency, ms, cloud, source;
    std::uint64_t id = 0;
    if (words >> tool >> latency >> ms >> cloud >> id >> source && latency == "latency_ms") ids[source] = id;
  }
  return ids;
}

TEST(DdsBadSamples, EverySampleGivesOneResultNamingTheProblem) {
  Pipeline p("bad-samples", domains::bad_samples);
  const std::string config = p.dir() + "/pipeline.yaml";
  std::ofstream(config) << "input:\n  max_points: " << kMaxPoints << "\n";
  const std::vector<Sample> sent = samples();
  p.start_echo(static_cast<int>(sent.size()) + 1, {"--latency"});
  for (const std::string& stage : kStages) p.start_service(stage, {"--config", config});

  {
    dds::Participant participant(std::stoi(p.domain()), "bad-samples-test");
    dds::Writer<decltype(dds::topics::raw_cloud)> writer(participant, dds::topics::raw_cloud);
    ASSERT_TRUE(writer.wait_for_readers(1, kStartWait)) << "ingest did not come up";
    std::uint64_t id = 0;
    for (const Sample& s : sent) {
      msg::RawCloud m;
      m.header().cloud_id(id++);
      m.header().source(s.source);
      m.header().object_count(s.object_count);
      m.xyz(s.xyz);
      m.width(s.width);
      m.height(s.height);
      m.pixel(s.pixel);
      ASSERT_TRUE(writer.write(m));
    }
    EXPECT_TRUE(writer.wait_for_acknowledgments(120s));
  }
  {
    // Another participant, so that the type name can stand for the corrupting type.
    dds::Participant participant(std::stoi(p.domain()), "bad-samples-corrupt");
    dds::Writer<decltype(kCorruptRawCloud)> writer(participant, kCorruptRawCloud);
    ASSERT_TRUE(writer.wait_for_readers(1, kStartWait)) << "ingest did not come up";
    msg::RawCloud m;
    m.header().cloud_id(kUndecodableId);
    m.header().source("undecodable");
    m.xyz({1, 2, 3});
    ASSERT_TRUE(writer.write(m));
    EXPECT_TRUE(writer.wait_for_acknowledgments(120s));
  }
  ASSERT_EQ(p.wait_echo(), 0) << "echo did not print one result per sample; its log:\n"
                              << read_text(p.log_path("echo"));

  const std::map<std::string, pipeline::RecognitionResult> results = by_source(p.echo_lines());
  ASSERT_EQ(results.size(), sent.size() + 1);
  const auto reason_of = [&](const std::string& source) {
    const pipeline::RecognitionResult& r = results.at(source);
    EXPECT_EQ(r.objects.size(), 1u) << source;
    if (r.objects.empty()) return std::string();
    EXPECT_EQ(r.objects[0].shape, "unknown") << source;
    EXPECT_TRUE(r.objects[0].dimensions.empty()) << source;
    return r.objects[0].reason;
  };
  EXPECT_THAT(reason_of("all_nan"), HasSubstr("ingest: no usable points (all 100 points have NaN"));
  EXPECT_THAT(reason_of("ten_values"), HasSubstr("ingest: xyz holds 10 values, not whole x y z triples"));
  EXPECT_THAT(reason_of("zero_points"), HasSubstr("ingest: no points"));
  EXPECT_THAT(reason_of("over_limit"), HasSubstr("ingest: 5001 points, more than input.max_points 5000"));
  EXPECT_THAT(reason_of("one_point"), HasSubstr("too few points"));
  EXPECT_THAT(reason_of("three_points"), HasSubstr("too few points"));
  EXPECT_THAT(reason_of("repeated_point"), HasSubstr("all points coincide"));
  EXPECT_THAT(reason_of("collinear"), HasSubstr("collinear"));
  EXPECT_THAT(reason_of("coplanar"), HasSubstr("coplanar"));
  EXPECT_THAT(reason_of("pixel_beyond_grid"), HasSubstr("ingest: pixel[3999] = 5000 is outside the 100 x 50 grid"));
  // It names its cloud: id and source still read from the start of the broken sample.
  EXPECT_THAT(reason_of("undecodable"), HasSubstr("receive: the sample does not deserialize"));
  const std::map<std::string, std::uint64_t> ids = echoed_ids(read_text(p.log_path("echo")));
  ASSERT_EQ(ids.count("undecodable"), 1u) << read_text(p.log_path("echo"));
  EXPECT_EQ(ids.at("undecodable"), kUndecodableId);
  EXPECT_EQ(ids.at("ten_values"), 2u);
  // Readable clouds: the NaN points are dropped, the sensor's object_count 0 is ignored.
  for (const char* source : {"some_nan", "object_count_zero"}) {
    const pipeline::RecognitionResult& r = results.at(source);
    ASSERT_EQ(r.objects.size(), 1u) << source;
    EXPECT_EQ(r.objects[0].shape, "box") << source << ": " << r.objects[0].reason;
  }
  EXPECT_EQ(results.at("some_nan").points_in, 3998u);
  EXPECT_EQ(results.at("object_count_zero").points_in, 4000u);

  p.stop_services();
}

}  // namespace
}  // namespace cloudshape::testing
