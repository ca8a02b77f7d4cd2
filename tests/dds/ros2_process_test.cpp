// Process-level ROS 2 tests: the five services with ingest reading a sensor_msgs/PointCloud2 topic
// and only ROS 2 readers downstream (no cloudshape-echo), so their readers must bring the chain up.
// A Cyclone DDS program (types from its own IDL) and a Fast DDS publisher with ROS 2's default
// profile get, for organized and unorganized clouds in float32 and float64 layouts, the shapes,
// dimensions and poses cloudshape-recognize finds in the same points, with their stamps and frame;
// bad PointCloud2 layouts each give one error result naming the problem, and nothing else.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <thread>

#include "corrupt_sample.hpp"
#include "dds/endpoints.hpp"
#include "dds/ros2_topics.hpp"
#include "io/cloud_reader.hpp"
#include "io/cloud_writers.hpp"
#include "io/pointcloud2_encode.hpp"
#include "pipeline_harness.hpp"
#include "ros2/messages.hpp"
#include "ros2_interop/ros2_compare.hpp"
#include "test_domains.hpp"

namespace cloudshape::testing {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;

const std::string kTopic = "/camera/points";
const std::string kDdsTopic = "rt/camera/points";
const std::string kFrameId = "camera_depth_optical_frame";

// One frame of a test: the points as sent (the grid of an organized one), the file recognize reads
// with exactly those points, and the coordinate type of its PointCloud2.
struct Frame {
  std::string name;
  std::string pcd;
  io::CloudFile cloud;
  bool f64 = false;
};

// The stamp of frame i (the Cyclone node stamps its frames so too).
io::RosHeader frame_header(std::size_t i) {
  return {{static_cast<std::int32_t>(1000 + i), static_cast<std::uint32_t>(1000 * i + 7)}, kFrameId};
}

// Six synthetic solids (float32 PCD) sent as float32, the same with coordinates that float32
// cannot hold (float64 PCD) sent as float64, and an organized depth-camera scene sent both ways.
std::vector<Frame> make_frames(const std::string& dir, int points, bool organized_scene) {
  std::vector<Frame> frames;
  const std::vector<std::string> solids = synthetic_clouds(dir + "/solids", points);
  for (const std::string& file : solids) {
    const std::string stem = fs::path(file).stem().string();
    const PointList original = io::read_cloud(file).points;
    const std::string f32 = dir + "/" + stem + "_f32.pcd";
    io::write_pcd(f32, original, io::PcdEncoding::binary, false);
    frames.push_back({stem + " float32", f32, io::read_cloud(f32), false});
    PointList fine = original;
    for (std::size_t k = 0; k < fine.size(); ++k) fine[k] += Eigen::Vector3d(1, -2, 3) * (1e-9 * static_cast<double>(k % 7));
    const std::string f64 = dir + "/" + stem + "_f64.pcd";
    io::write_pcd(f64, fine, io::PcdEncoding::binary, true);
    frames.push_back({stem + " float64", f64, io::read_cloud(f64), true});
  }
  if (organized_scene) {
    const std::string scene = dir + "/scene.pcd";
    const ProcessResult r = run_process({kBin + "/cloudshape-synth", "scene", "--layout", "row", "--count", "2",
                                         "--seed", "3", "--width", "320", "--height", "240", "-o", scene});
    if (r.exit_code != 0) throw std::runtime_error("cloudshape-synth scene failed: " + r.err);
    const io::CloudFile cloud = io::read_cloud(scene);
    if (!cloud.grid.organized()) throw std::runtime_error("the scene is not organized");
    frames.push_back({"organized scene float32", scene, cloud, false});
    frames.push_back({"organized scene float64", scene, cloud, true});
  }
  return frames;
}

io::PointCloud2Layout layout_of(const Frame& f) { return f.f64 ? io::float64_layout() : io::PointCloud2Layout{}; }

// recognize's result of each frame's file, named as the services name a ROS 2 cloud: its topic.
std::vector<pipeline::RecognitionResult> expected_results(const std::vector<Frame>& frames) {
  std::vector<std::string> files;
  for (const Frame& f : frames) files.push_back(f.pcd);
  std::vector<std::string> unique = files;
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  const auto results = by_source(recognize(unique));
  std::vector<pipeline::RecognitionResult> out;
  for (const Frame& f : frames) {
    pipeline::RecognitionResult r = results.at(fs::path(f.pcd).filename().string());
    EXPECT_FALSE(r.objects.empty()) << f.name;
    r.source = kTopic;
    out.push_back(r);
  }
  return out;
}

// The Cyclone node's frame file: "width height", then every pixel's x y z (NaN where none).
std::string write_frame_text(const std::string& path, const io::CloudFile& cloud) {
  const bool organized = cloud.grid.organized();
  const std::size_t width = organized ? cloud.grid.width : cloud.points.size();
  const std::size_t height = organized ? cloud.grid.height : 1;
  std::ofstream out(path);
  out << width << ' ' << height << '\n';
  out.precision(17);
  std::size_t next = 0;
  for (std::size_t pixel = 0; pixel < width * height; ++pixel) {
    if (!organized || (next < cloud.points.size() && cloud.grid.pixel[next] == pixel)) {
      const Point& p = cloud.points[next++];
      out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    } else {
      out << "nan nan nan\n";
    }
  }
  return path;
}

// What the contract says in words, independently of common/ros2: per object its shape as
// class_id, confidence as score, pose.center as the position, and the box's edges as its size.
void expect_shapes_and_poses(const json& detections, const pipeline::RecognitionResult& expected,
                             const std::string& frame) {
  ASSERT_EQ(detections["detections"].size(), expected.objects.size()) << frame;
  for (std::size_t k = 0; k < expected.objects.size(); ++k) {
    const pipeline::ObjectResult& o = expected.objects[k];
    const json& d = detections["detections"][k];
    EXPECT_EQ(d["results"][0]["class_id"], o.shape) << frame;
    EXPECT_NEAR(d["results"][0]["score"].get<double>(), o.confidence, 1e-9) << frame;
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(d["results"][0]["pose"]["position"][a].get<double>(), o.center[a],
                  1e-9 * std::max(1.0, std::abs(o.center[a])))
          << frame;
    }
    if (o.shape == "box") {
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(d["bbox"]["size"][a].get<double>(), o.dimensions[a].second, 1e-9 * o.dimensions[a].second)
            << frame;
      }
    }
  }
}

void start_services(Pipeline& p) {
  for (const std::string& s : kStages) {
    p.start_service(s, s == "ingest" ? std::vector<std::string>{"--ros-topic", kTopic} : std::vector<std::string>{});
  }
}

TEST(DdsRos2, CycloneNodeGetsWhatRecognizeFinds) {
#ifndef CLOUDSHAPE_ROS2_CYCLONE_NODE
  GTEST_SKIP() << "ros2_cyclone_node not built (needs cyclonedds-dev, cyclonedds-tools)";
#else
  Pipeline p("ros2_cyclone", domains::ros2_cyclone);
  const std::vector<Frame> frames = make_frames(p.dir(), 6000, true);
  const std::vector<pipeline::RecognitionResult> expected = expected_results(frames);
  std::vector<std::string> argv = {CLOUDSHAPE_ROS2_CYCLONE_NODE, "--domain", p.domain(), "--topic", kTopic,
                                   "--frame-id", kFrameId, "--timeout", std::to_string(kEchoTimeoutS)};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::string text = write_frame_text(p.dir() + "/frame" + std::to_string(i) + ".txt", frames[i].cloud);
    argv.push_back(text + (frames[i].f64 ? ":float64" : ":float32"));
  }
  // Cyclone on loopback with unicast discovery, like the Fast DDS side (config/qos.xml).
  setenv("CYCLONEDDS_URI", "file://" CLOUDSHAPE_SOURCE_DIR "/config/cyclonedds_localhost.xml", 1);
  const pid_t node = p.start_other(argv, "node.jsonl");
  start_services(p);
  ASSERT_EQ(p.wait_other(node), 0) << read_text(p.log_path("node")) << read_text(p.log_path("ingest"));
  const std::vector<std::string> lines = lines_of(read_text(p.dir() + "/node.jsonl"));
  ASSERT_EQ(lines.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const json got = json::parse(lines[i]);
    EXPECT_EQ(got["frame"], i);
    EXPECT_EQ(got["detections"]["detections"].size(), expected[i].objects.size()) << frames[i].name;
    EXPECT_EQ(ros_results_difference(got["detections"], got["markers"], expected[i], frame_header(i)), "")
        << frames[i].name;
    expect_shapes_and_poses(got["detections"], expected[i], frames[i].name);
  }
  p.stop_services();
#endif
}

// A ROS 2 participant of the test: publishes clouds on kTopic with ROS 2's default profile
// (RELIABLE, KEEP_LAST 10) and reads the two result topics with it.
class RosNode {
 public:
  explicit RosNode(const Pipeline& p)
      : participant_(std::stoi(p.domain()), "ros2-test-node"),
        cloud_spec_{kDdsTopic.c_str()},
        cloud_(participant_, cloud_spec_, dds::Traffic::ros2_default),
        detections_(participant_, detections_spec_, dds::Traffic::ros2_default),
        markers_(participant_, markers_spec_, dds::Traffic::ros2_default) {}

  dds::Participant& participant() { return participant_; }
  bool wait_for_ingest() { return cloud_.wait_for_readers(1, kStartWait); }

  void publish(io::PointCloud2 cloud) {
    sensor_msgs::msg::PointCloud2 m = ros2::to_msg(std::move(cloud));
    cloud_.write(m);
    ++sent_;
  }

  // The results stamped `stamp`, as JSON; waits up to `timeout`. Others are dropped (counted).
  bool results_of(const io::RosTime& stamp, std::chrono::milliseconds timeout, json& detections, json& markers) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while ((detections.is_null() || markers.is_null()) && std::chrono::steady_clock::now() < deadline) {
      vision_msgs::msg::Detection3DArray d;
      if (detections_.take(d, 20ms)) {
        ++detection_arrays_;
        if (d.header().stamp().sec() == stamp.sec && d.header().stamp().nanosec() == stamp.nanosec &&
            detections.is_null()) {
          detections = detections_json(d);
        }
      }
      visualization_msgs::msg::MarkerArray m;
      if (markers_.take(m, 20ms) && !m.markers().empty() && m.markers()[0].header().stamp().sec() == stamp.sec &&
          m.markers()[0].header().stamp().nanosec() == stamp.nanosec && markers.is_null()) {
        markers = markers_json(m);
      }
    }
    return !detections.is_null() && !markers.is_null();
  }

  // Every Detection3DArray taken so far, after waiting `quiet` for more.
  int detection_arrays(std::chrono::milliseconds quiet) {
    vision_msgs::msg::Detection3DArray d;
    while (detections_.take(d, quiet)) ++detection_arrays_;
    return detection_arrays_;
  }
  int sent() const { return sent_; }

 private:
  dds::Participant participant_;
  dds::PointCloud2PublishTopic cloud_spec_;
  dds::DetectionsTopic detections_spec_{"rt/cloudshape/detections"};
  dds::MarkersTopic markers_spec_{"rt/cloudshape/markers"};
  dds::Writer<dds::PointCloud2PublishTopic> cloud_;
  dds::Reader<dds::DetectionsTopic> detections_;
  dds::Reader<dds::MarkersTopic> markers_;
  int sent_ = 0;
  int detection_arrays_ = 0;
};

// Publishes `cloud` until its results come (the writer is RELIABLE, ingest's reader BEST_EFFORT:
// a lost fragment loses the frame).
bool publish_and_wait(RosNode& node, const io::PointCloud2& cloud, json& detections, json& markers) {
  for (int attempt = 0; attempt < 8; ++attempt) {
    node.publish(cloud);
    if (node.results_of(cloud.header.stamp, 20s, detections, markers)) return true;
    std::cerr << "no results in 20 s: sent again\n";
  }
  return false;
}

TEST(DdsRos2, FastDdsDefaultProfilePublisherAndALateReader) {
  Pipeline p("ros2_fastdds", domains::ros2_fastdds);
  const std::vector<Frame> all = make_frames(p.dir(), 5000, true);
  // A subset keeps the test short: both layouts of two solids and of the scene.
  std::vector<Frame> frames;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (i < 4 || i + 2 >= all.size()) frames.push_back(all[i]);
  }
  const std::vector<pipeline::RecognitionResult> expected = expected_results(frames);
  RosNode node(p);
  start_services(p);
  ASSERT_TRUE(node.wait_for_ingest()) << read_text(p.log_path("ingest"));
  // The late reader is a participant of its own, as RViz started later would be.
  std::unique_ptr<dds::Participant> late_participant;
  std::unique_ptr<dds::Reader<dds::DetectionsTopic>> late;
  dds::DetectionsTopic late_spec{"rt/cloudshape/detections"};
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const io::PointCloud2 cloud =
        io::encode_pointcloud2(frames[i].cloud.points, frames[i].cloud.grid, layout_of(frames[i]), frame_header(i));
    json detections, markers;
    ASSERT_TRUE(publish_and_wait(node, cloud, detections, markers)) << frames[i].name;
    EXPECT_EQ(ros_results_difference(detections, markers, expected[i], frame_header(i)), "") << frames[i].name;
    if (late) {
      // The reader that joined after the first frame has this frame's detections too.
      vision_msgs::msg::Detection3DArray d;
      bool found = false;
      const auto deadline = std::chrono::steady_clock::now() + 30s;
      while (!found && std::chrono::steady_clock::now() < deadline) {
        found = late->take(d, 100ms) && d.header().stamp().sec() == cloud.header.stamp.sec;
      }
      EXPECT_TRUE(found) << "the late reader missed " << frames[i].name;
    }
    if (i == 0) {
      const auto joined = std::chrono::steady_clock::now();
      late_participant = std::make_unique<dds::Participant>(std::stoi(p.domain()), "ros2-test-late-reader");
      late = std::make_unique<dds::Reader<dds::DetectionsTopic>>(*late_participant, late_spec,
                                                                 dds::Traffic::ros2_default);
      while (late->matched_writers() == 0 && std::chrono::steady_clock::now() - joined < 30s) {
        std::this_thread::sleep_for(10ms);
      }
      const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - joined).count();
      std::cout << "the late reader matched the solver's writer " << ms << " ms after it joined\n";
      // The issue asks for a second; the budget allows for a loaded machine.
      EXPECT_LT(ms, 5000.0);
    }
  }
  p.stop_services();
}

// A PointCloud2 type that breaks every sample it writes: is_bigendian, a CDR boolean, set to 2.
class BreakingPointCloud2Type : public sensor_msgs::msg::PointCloud2PubSubType {
 public:
  bool serialize(void* data, SerializedPayload_t* payload) override {
    auto* m = static_cast<sensor_msgs::msg::PointCloud2*>(data);
    sensor_msgs::msg::PointCloud2 flipped = *m;
    flipped.is_bigendian(!m->is_bigendian());
    const auto a = serialized<sensor_msgs::msg::PointCloud2PubSubType>(*m);
    const auto b = serialized<sensor_msgs::msg::PointCloud2PubSubType>(flipped);
    if (!PointCloud2PubSubType::serialize(data, payload)) return false;
    for (std::uint32_t i = 0; i < a->length; ++i) {
      if (a->data[i] != b->data[i]) payload->data[i] = 2;
    }
    return true;
  }
};

struct BadCloud {
  std::string name;
  std::function<void(io::PointCloud2&)> spoil;
  std::string reason;  // what the result's reason must contain
};

TEST(DdsRos2, BadPointCloud2GivesOneErrorResultNamingTheProblem) {
  Pipeline p("ros2_bad", domains::ros2_bad_clouds);
  const PointList points = io::read_cloud(synthetic_clouds(p.dir() + "/solids", 3000).front()).points;
  const std::vector<BadCloud> bad = {
      {"no z", [](io::PointCloud2& c) { c.fields[2].name = "depth"; },
       "ingest: fields: no field named 'z' (fields: x, y, depth, rgb)"},
      {"offset past point_step", [](io::PointCloud2& c) { c.fields[3].offset = 14; },
       "ingest: field 'rgb': offset 14 + 1 x FLOAT32 ends at byte 18, past point_step 16"},
      {"count past point_step", [](io::PointCloud2& c) { c.fields[1].count = 4; },
       "ingest: field 'y': offset 4 + 4 x FLOAT32 ends at byte 20, past point_step 16"},
      {"data short", [](io::PointCloud2& c) { c.data.resize(c.data.size() - 16); }, "ingest: data: "},
      {"width x height disagrees", [](io::PointCloud2& c) { c.height = 2; }, "fewer than row_step * height"},
      {"row_step short", [](io::PointCloud2& c) { c.width += 1; }, "ingest: row_step: "},
  };
  RosNode node(p);
  // cloudshape_result too: exactly one error result per cloud sent there as well.
  dds::Reader<decltype(dds::topics::result)> results(node.participant(), dds::topics::result);
  int result_samples = 0;
  const auto result_stamped = [&](std::int32_t sec) {
    msg::ShapeResult r;
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (std::chrono::steady_clock::now() < deadline) {
      if (!results.take(r, 100ms)) continue;
      ++result_samples;
      if (r.header().sensor().stamp_sec() == sec) return r;
    }
    ADD_FAILURE() << "no result stamped " << sec;
    return msg::ShapeResult();
  };
  start_services(p);
  ASSERT_TRUE(node.wait_for_ingest()) << read_text(p.log_path("ingest"));
  for (std::size_t i = 0; i < bad.size(); ++i) {
    io::PointCloud2 cloud = io::encode_pointcloud2(points, {}, {}, frame_header(i));
    bad[i].spoil(cloud);
    json detections, markers;
    ASSERT_TRUE(publish_and_wait(node, cloud, detections, markers)) << bad[i].name;
    ASSERT_EQ(detections["detections"].size(), 1u) << bad[i].name;
    EXPECT_EQ(detections["detections"][0]["results"][0]["class_id"], "unknown") << bad[i].name;
    EXPECT_EQ(detections["header"]["frame_id"], kFrameId);
    ASSERT_EQ(markers.size(), 2u) << bad[i].name;  // DELETEALL and the label
    EXPECT_THAT(markers[1]["text"].get<std::string>(), ::testing::HasSubstr(bad[i].reason)) << bad[i].name;
    const msg::ShapeResult r = result_stamped(frame_header(i).stamp.sec);
    EXPECT_EQ(r.header().source(), kTopic);
    ASSERT_EQ(r.objects().size(), 1u) << bad[i].name;
    EXPECT_THAT(r.objects()[0].reason(), ::testing::HasSubstr(bad[i].reason)) << bad[i].name;
  }
  // A sample that does not even deserialize: one error result, stamped at its sending.
  int breaker_sent = 0;
  {
    const dds::TopicSpec<sensor_msgs::msg::PointCloud2, BreakingPointCloud2Type> breaking{kDdsTopic.c_str()};
    dds::Participant other(std::stoi(p.domain()), "ros2-test-breaker");
    dds::Writer<decltype(breaking)> writer(other, breaking, dds::Traffic::ros2_default);
    ASSERT_TRUE(writer.wait_for_readers(1, kStartWait));
    sensor_msgs::msg::PointCloud2 m = ros2::to_msg(io::encode_pointcloud2(points, {}, {}, frame_header(99)));
    msg::ShapeResult r;
    bool got = false;
    for (int attempt = 0; attempt < 8 && !got; ++attempt) {
      writer.write(m);
      ++breaker_sent;
      got = results.take(r, 20s);
    }
    ASSERT_TRUE(got);
    ++result_samples;
    // Its header could not be read: the results go out in ros2.file_frame_id.
    EXPECT_EQ(r.header().sensor().frame_id(), "");
    ASSERT_EQ(r.objects().size(), 1u);
    EXPECT_THAT(r.objects()[0].reason(),
                ::testing::HasSubstr("ingest: the sample does not deserialize as sensor_msgs/PointCloud2"));
  }
  // Nothing else: one result per cloud sent on either topic, none later.
  msg::ShapeResult extra;
  while (results.take(extra, 3s)) ++result_samples;
  const int sent = node.sent() + breaker_sent;
  EXPECT_EQ(result_samples, sent);
  EXPECT_EQ(node.detection_arrays(3s), sent);
  p.stop_services();
}

}  // namespace
}  // namespace cloudshape::testing
