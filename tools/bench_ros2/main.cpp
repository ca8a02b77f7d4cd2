// cloudshape-bench-ros2: what a ROS 2 PointCloud2 costs end to end against a raw cloud of the
// same points, through the running services (ingest with --ros-topic TOPIC).
//   cloudshape-bench-ros2 [--domain N] [--topic /bench/points] [--frames 15] [--point-step 16|32] FILE.pcd
// Sends the file's points one cloud at a time, alternately as cloudshape_raw_cloud and as
// sensor_msgs/PointCloud2 (float32 x y z and rgb, ROS 2 sensor-data QoS), waits for each
// result on cloudshape_result and prints per kind the median end-to-end latency (write -> result
// taken) and overhead (latency minus the stage times the services measured for that cloud), and
// the median per-pair overhead difference: what the PointCloud2 adds. Last line: JSON (with
// "resent": clouds sent again after 10 s without a result).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dds/convert.hpp"
#include "dds/endpoints.hpp"
#include "dds/participant_cli.hpp"
#include "dds/result_joiner.hpp"
#include "dds/ros2_topics.hpp"
#include "io/cloud_reader.hpp"
#include "io/pointcloud2_encode.hpp"
#include "ros2/messages.hpp"

namespace {
namespace cs = cloudshape;
using Clock = std::chrono::steady_clock;
constexpr const char* kTool = "cloudshape-bench-ros2";
// A 10 MB best-effort frame overruns a loaded host's socket buffers now and then: sent again,
// it is timed from its new write, so a loss costs time but biases nothing.
constexpr int kAttempts = 10;

long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// float32 x y z and a packed rgb: 16 bytes, or PCL's aligned PointXYZRGB of 32.
cs::io::PointCloud2Layout layout_of(std::uint32_t point_step) {
  cs::io::PointCloud2Layout layout;
  layout.point_step = point_step;
  layout.rgb_offset = point_step == 32 ? 16 : 12;
  return layout;
}

struct Sample {
  double latency_ms = 0.0;
  double overhead_ms = 0.0;
};

class Bench {
 public:
  Bench(cs::dds::Participant& p, const std::string& dds_topic)
      : cloud_spec_{dds_topic.c_str()},
        raw_(p, cs::dds::topics::raw_cloud),
        ros_(p, cloud_spec_, cs::dds::Traffic::ros2_sensor_data),
        results_(p, cs::dds::topics::result) {}

  bool wait_for_ingest(std::chrono::seconds timeout) {
    return raw_.wait_for_readers(1, timeout) && ros_.wait_for_readers(1, timeout);
  }

  int resent() const { return resent_; }

  // Sends one cloud and waits for its result (sent again after 10 s: best effort may lose it).
  bool raw(cs::msg::RawCloud& cloud, Sample& out) {
    return round_trip([&] {
      cloud.header().inject_time_ns(now_ns());
      raw_.write(cloud);
    }, [&](const cs::msg::CloudHeader& h) { return h.cloud_id() == cloud.header().cloud_id() && h.source() == "raw"; }, out);
  }

  bool ros(sensor_msgs::msg::PointCloud2& cloud, Sample& out) {
    return round_trip([&] { ros_.write(cloud); }, [&](const cs::msg::CloudHeader& h) {
      return h.sensor().stamp_sec() == cloud.header().stamp().sec() &&
             h.sensor().stamp_nanosec() == cloud.header().stamp().nanosec();
    }, out);
  }

 private:
  template <class Send, class Mine>
  bool round_trip(Send send, Mine mine, Sample& out) {
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
      if (attempt > 0) ++resent_;
      send();
      const auto deadline = Clock::now() + std::chrono::seconds(10);
      cs::msg::ShapeResult r;
      while (Clock::now() < deadline) {
        if (!results_.take(r, std::chrono::milliseconds(100))) continue;
        const auto cloud = joiner_.add(std::move(r));
        if (!cloud || !mine(cloud->front().header())) continue;
        const long long received = now_ns();
        out.latency_ms = static_cast<double>(received - cloud->front().header().inject_time_ns()) / 1e6;
        out.overhead_ms = out.latency_ms - cs::dds::to_recognition_result(*cloud).timings.total_ms;
        return true;
      }
      std::fprintf(stderr, "%s: no result in 10 s, sending again\n", kTool);
    }
    return false;
  }

  cs::dds::PointCloud2PublishTopic cloud_spec_;
  cs::dds::Writer<decltype(cs::dds::topics::raw_cloud)> raw_;
  cs::dds::Writer<cs::dds::PointCloud2PublishTopic> ros_;
  cs::dds::Reader<decltype(cs::dds::topics::result)> results_;
  cs::dds::ResultJoiner joiner_;
  int resent_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Latency of a ROS 2 PointCloud2 against a raw cloud of the same points, end to end.", kTool};
  cs::dds::ParticipantArgs participant_args;
  std::string topic = "/bench/points", file;
  int frames = 15;
  std::uint32_t point_step = 16;
  cs::dds::add_participant_options(app, participant_args);
  app.add_option("--topic", topic, "the ROS 2 topic ingest reads (--ros-topic)");
  app.add_option("--frames", frames, "clouds of each kind")->check(CLI::PositiveNumber);
  app.add_option("--point-step", point_step, "bytes per point: 16 or 32")->check(CLI::IsMember({16, 32}));
  app.add_option("FILE", file, "the cloud (an organized 640 x 480 PCD: a depth camera frame)")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    const cs::io::CloudFile cloud = cs::io::read_cloud(file);
    cs::msg::RawCloud raw = cs::dds::to_raw_cloud(cloud.points, cloud.grid);
    raw.header().source("raw");
    const std::string dds_topic = cs::dds::ros2_dds_topic(topic);
    cs::dds::Participant participant = cs::dds::open_participant(participant_args, kTool);
    Bench bench(participant, dds_topic);
    if (!bench.wait_for_ingest(std::chrono::seconds(60))) {
      std::fprintf(stderr, "%s: no ingest reading cloudshape_raw_cloud and %s\n", kTool, dds_topic.c_str());
      return 1;
    }
    std::vector<Sample> raws, roses;
    std::vector<double> differences;
    const int warm_up = 2;
    for (int i = 0; i < frames + warm_up; ++i) {
      raw.header().cloud_id(static_cast<std::uint64_t>(i + 1));
      const cs::io::RosHeader header{{i, 0}, "bench"};
      sensor_msgs::msg::PointCloud2 ros =
          cs::ros2::to_msg(cs::io::encode_pointcloud2(cloud.points, cloud.grid, layout_of(point_step), header));
      Sample a, b;
      // Alternate which goes first, so neither always meets warmer caches.
      const bool ok = i % 2 ? bench.raw(raw, a) && bench.ros(ros, b) : bench.ros(ros, b) && bench.raw(raw, a);
      if (!ok) {
        std::fprintf(stderr, "%s: frame %d: no result\n", kTool, i);
        return 1;
      }
      if (i < warm_up) continue;
      raws.push_back(a);
      roses.push_back(b);
      differences.push_back(b.overhead_ms - a.overhead_ms);
      std::fprintf(stderr, "%s: frame %d: raw %.2f ms (overhead %.2f), PointCloud2 %.2f ms (overhead %.2f)\n", kTool,
                   i - warm_up, a.latency_ms, a.overhead_ms, b.latency_ms, b.overhead_ms);
    }
    const auto field = [](const std::vector<Sample>& v, double Sample::*f) {
      std::vector<double> out;
      for (const Sample& s : v) out.push_back(s.*f);
      return median(out);
    };
    const std::size_t pixels = cloud.grid.organized() ? cloud.grid.width * cloud.grid.height : cloud.points.size();
    std::printf("| points | point_step | raw cloud latency | PointCloud2 latency | raw overhead | PointCloud2 overhead | "
                "added by PointCloud2 (median of pairs) | sent again |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::printf("| %zu (%zu pixels) | %u | %.2f ms | %.2f ms | %.2f ms | %.2f ms | %.2f ms | %d |\n", cloud.points.size(),
                pixels, point_step, field(raws, &Sample::latency_ms), field(roses, &Sample::latency_ms),
                field(raws, &Sample::overhead_ms), field(roses, &Sample::overhead_ms), median(differences),
                bench.resent());
    nlohmann::json j = {{"points", cloud.points.size()},
                        {"pixels", pixels},
                        {"point_step", point_step},
                        {"frames", frames},
                        {"raw_latency_ms", field(raws, &Sample::latency_ms)},
                        {"pointcloud2_latency_ms", field(roses, &Sample::latency_ms)},
                        {"raw_overhead_ms", field(raws, &Sample::overhead_ms)},
                        {"pointcloud2_overhead_ms", field(roses, &Sample::overhead_ms)},
                        {"added_ms", median(differences)},
                        {"resent", bench.resent()}};
    std::printf("%s\n", j.dump().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", kTool, e.what());
    return 1;
  }
}
