// cloudshape-inject replaying an MCAP recording through the five services: every PointCloud2
// message delivered at its recorded time, and echo printing for "rec.mcap#N" what
// cloudshape-recognize prints for the same message.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "io/cloud_reader.hpp"
#include "io/mcap_reader.hpp"
#include "io/mcap_writer.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/ros2_schemas.hpp"
#include "io/pointcloud2_encode.hpp"
#include "pipeline_harness.hpp"
#include "test_domains.hpp"

namespace cloudshape::testing {
namespace {

constexpr std::uint64_t kSecond = 1'000'000'000;

// The synthetic suite's clouds as PointCloud2 messages `gap` apart (0.4 s) on /camera/points
// (float32 and float64 alternating), with one cloud on /other in between.
std::string write_recording(const std::string& dir, const std::vector<std::string>& clouds,
                            const io::McapWriterOptions& options = {}, std::uint64_t gap = 4 * kSecond / 10) {
  const std::string path = dir + "/rec.mcap";
  io::McapWriter writer(path, options);
  const auto schema =
      writer.add_schema(io::kPointCloud2SchemaName, "ros2msg", io::ros2_schema_text(io::kPointCloud2SchemaName));
  const auto camera = writer.add_channel(schema, "/camera/points", "cdr");
  const auto other = writer.add_channel(schema, "/other", "cdr");
  std::uint64_t t = 50 * kSecond;
  for (std::size_t i = 0; i < clouds.size(); ++i) {
    const io::CloudFile cloud = io::read_cloud(clouds[i]);
    const io::PointCloud2Layout layout = i % 2 ? io::float64_layout() : io::PointCloud2Layout{};
    const std::string cdr =
        io::pointcloud2_to_cdr(io::encode_pointcloud2(cloud.points, cloud.grid, layout, {{50, 0}, "camera"}));
    writer.write(camera, t, t, cdr);
    if (i == 0) writer.write(other, t + kSecond / 10, t, cdr);
    t += gap;
  }
  writer.close();
  return path;
}

TEST(DdsMcapReplay, EveryMessageAtItsTimeGivesWhatRecognizeGives) {
  Pipeline p("mcap_replay", domains::mcap_replay);
  std::vector<std::string> clouds = synthetic_clouds(p.dir() + "/clouds", 8000);
  clouds.resize(4);
  const std::string rec = write_recording(p.dir(), clouds);
  std::vector<std::string> expected;
  for (const std::string& line : recognize({rec})) {
    if (line.find("\"rec.mcap#1\"") == std::string::npos) expected.push_back(line);  // #1 is on /other
  }
  ASSERT_EQ(expected.size(), 4u);

  p.start_echo(4);
  for (const std::string& s : kStages) p.start_service(s);
  const auto started = std::chrono::steady_clock::now();
  const ProcessResult inj = p.inject({"--topic", "/camera/points", rec});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(inj.exit_code, 0) << inj.err;
  EXPECT_NE(inj.err.find("rec.mcap: 4 cloud(s) replayed"), std::string::npos) << inj.err;
  // Three gaps of 0.4 s as recorded; the waits for results come on top.
  EXPECT_GE(seconds, 1.2) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << "echo did not print every result; its log:\n" << read_text(p.log_path("echo"));
  expect_same_results(expected, p.echo_lines());
  p.stop_services();
}

// inject --start 3 on a recording of a chunk per message: messages 3 and 4 only, named as
// recognize --start names them, through the index (no note that the file has none).
TEST(DdsMcapReplay, StartSeeksToAMessage) {
  Pipeline p("mcap_replay_start", domains::mcap_replay_start);
  std::vector<std::string> clouds = synthetic_clouds(p.dir() + "/clouds", 8000);
  clouds.resize(4);
  io::McapWriterOptions options;
  options.chunk_size = 1;
  const std::string rec = write_recording(p.dir(), clouds, options);
  const std::vector<std::string> expected = recognize({"--start", "3", rec});
  ASSERT_EQ(expected.size(), 2u);
  EXPECT_NE(expected[0].find("\"rec.mcap#3\""), std::string::npos) << expected[0];

  p.start_echo(2);
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject({"--start", "3", rec});
  EXPECT_EQ(inj.exit_code, 0) << inj.err;
  EXPECT_NE(inj.err.find("sent rec.mcap#3 as cloud 0"), std::string::npos) << inj.err;
  EXPECT_NE(inj.err.find("sent rec.mcap#4 as cloud 1"), std::string::npos) << inj.err;
  EXPECT_EQ(inj.err.find("rec.mcap#2"), std::string::npos) << inj.err;
  EXPECT_EQ(inj.err.find("no usable index"), std::string::npos) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  expect_same_results(expected, p.echo_lines());
  p.stop_services();
}

// A recording far faster than the services (24 clouds 1 ms apart): inject holds back at the
// raw-cloud readers' history (8 in qos.xml) instead of running ahead of a busy ingest, which would
// then refuse samples that DDS sends again and again; every cloud still gives recognize's result.
TEST(DdsMcapReplay, AReplayFasterThanTheServicesWaitsAtTheReadersHistory) {
  Pipeline p("mcap_replay_backpressure", domains::mcap_replay_backpressure);
  const std::vector<std::string> suite = synthetic_clouds(p.dir() + "/clouds", 8000);
  std::vector<std::string> clouds;
  for (std::size_t i = 0; clouds.size() < 24; ++i) clouds.push_back(suite[i % suite.size()]);
  const std::string rec = write_recording(p.dir(), clouds, {}, kSecond / 1000);
  const std::vector<std::string> expected = recognize({rec});
  ASSERT_EQ(expected.size(), 25u);  // with the one on /other

  p.start_echo(25);
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject({rec});
  EXPECT_EQ(inj.exit_code, 0) << inj.err;
  std::smatch most_pending;
  ASSERT_TRUE(std::regex_search(inj.err, most_pending, std::regex("at most ([0-9]+) awaiting their result"))) << inj.err;
  const int most = std::stoi(most_pending[1]);
  EXPECT_LE(most, 8) << inj.err;
  EXPECT_GE(most, 2) << "the replay never ran ahead of the services: " << inj.err;
  EXPECT_NE(inj.err.find("(--max-pending 8)"), std::string::npos) << inj.err;
  EXPECT_EQ(inj.err.find("sending it again"), std::string::npos) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  expect_same_results(expected, p.echo_lines());
  p.stop_services();
}

TEST(DdsMcapReplay, RateAndCountReplaceTheRecordedTimingAndBadRecordingsAreReported) {
  Pipeline p("mcap_replay_rate", domains::mcap_replay_rate);
  std::vector<std::string> clouds = synthetic_clouds(p.dir() + "/clouds", 8000);
  clouds.resize(2);
  const std::string rec = write_recording(p.dir(), clouds);
  const std::string fake = p.dir() + "/fake.mcap";
  { std::ofstream(fake) << "not a recording\n"; }
  // --count goes round the files: the recording's three clouds, then its first two again.
  p.start_echo(5);
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject({"--rate", "50", "--count", "5", fake, rec});
  EXPECT_EQ(inj.exit_code, 2) << inj.err;
  EXPECT_NE(inj.err.find(fake + ": byte 0: not an MCAP file"), std::string::npos) << inj.err;
  EXPECT_NE(inj.err.find("sent rec.mcap#2 as cloud 2"), std::string::npos) << inj.err;
  EXPECT_NE(inj.err.find("sent rec.mcap#1 as cloud 4"), std::string::npos) << inj.err;
  EXPECT_EQ(inj.err.find("as cloud 5"), std::string::npos) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  EXPECT_EQ(p.echo_lines().size(), 5u);
  p.stop_services();
}


// echo --record --record-clouds through the five services: the recording holds, per result echo
// printed, the cloud and its Detection3DArray and MarkerArray, and @mcap/core validates it.
TEST(DdsMcapRecord, EchoRecordsResultsAndTheirClouds) {
  Pipeline p("mcap_record", domains::mcap_record);
  std::vector<std::string> clouds = synthetic_clouds(p.dir() + "/clouds", 8000);
  clouds.resize(3);
  const std::string out = p.dir() + "/echo.mcap";
  p.start_echo(3, {"--record", out, "--record-clouds"});
  for (const std::string& s : kStages) p.start_service(s);
  // echo's raw-cloud reader is one subscriber, ingest the other.
  const ProcessResult inj = p.inject({"--subscribers", "2", clouds[0], clouds[1], clouds[2]});
  EXPECT_EQ(inj.exit_code, 0) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  p.stop_services();
  EXPECT_NE(read_text(p.log_path("echo")).find("echo.mcap: 9 messages recorded"), std::string::npos)
      << read_text(p.log_path("echo"));

  std::map<std::string, int> topics;
  const io::McapReadSummary summary = io::read_mcap_file(out, [&](const io::McapChannel& c, const io::McapSchema*,
                                                                  const io::McapMessage&) { ++topics[c.topic]; });
  EXPECT_TRUE(summary.summary_crc_checked);
  EXPECT_EQ(topics, (std::map<std::string, int>{
                        {"/cloudshape/detections", 3}, {"/cloudshape/markers", 3}, {"/cloudshape/points", 3}}));
  const ProcessResult check = run_process({CLOUDSHAPE_NODE, std::string(CLOUDSHAPE_SOURCE_DIR) +
                                                                "/tests/interop/mcap-node/check_recording.js",
                                           out, p.dir() + "/echo.jsonl", "--clouds"});
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  std::printf("%s", check.out.c_str());
}


// Recordings written by @mcap/core (tests/interop/mcap-node/write_clouds.js), replayed: echo
// prints what cloudshape-recognize prints for them (which the interop test holds equal to PCDs).
TEST(DdsMcapReplay, RecordingsWrittenByMcapCoreReplay) {
  Pipeline p("mcap_replay_node", domains::mcap_replay_node);
  std::vector<std::string> xyz;
  for (const auto& [shape, dims] : {std::pair<std::string, std::string>{"box", "30,20,10"}, {"sphere", "12"}}) {
    const std::string out = p.dir() + "/" + shape + ".xyz";
    const ProcessResult r = run_process({kBin + "/cloudshape-synth", "shape", "--shape", shape, "--dims", dims,
                                         "--points", "8000", "--seed", "5", "-o", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    xyz.push_back(out);
  }
  std::vector<std::string> node{CLOUDSHAPE_NODE,
                                std::string(CLOUDSHAPE_SOURCE_DIR) + "/tests/interop/mcap-node/write_clouds.js",
                                p.dir() + "/node"};
  node.insert(node.end(), xyz.begin(), xyz.end());
  const ProcessResult written = run_process(node);
  ASSERT_EQ(written.exit_code, 0) << written.err;
  const std::vector<std::string> recordings = {p.dir() + "/node/zstd_float32_organized.mcap",
                                               p.dir() + "/node/lz4_float64.mcap"};
  const std::vector<std::string> expected = recognize(recordings);
  ASSERT_EQ(expected.size(), 4u);
  p.start_echo(4);
  for (const std::string& s : kStages) p.start_service(s);
  const ProcessResult inj = p.inject({"--rate", "20", recordings[0], recordings[1]});
  EXPECT_EQ(inj.exit_code, 0) << inj.err;
  ASSERT_EQ(p.wait_echo(), 0) << read_text(p.log_path("echo"));
  expect_same_results(expected, p.echo_lines());
  p.stop_services();
}

}  // namespace
}  // namespace cloudshape::testing
