// cloudshape-echo [--domain N] [--security DIR] [--count N] [--timeout S] [--status] [--latency]
//                 [--record OUT.mcap [--record-clouds]]
// Prints every cloud's shape result once as one JSON line, the very object cloudshape-recognize
// prints (report::result_to_json_line); --status prints the services' status samples instead.
// --record writes the results (and their input clouds) to an MCAP recording as well.
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "dds/convert.hpp"
#include "dds/endpoints.hpp"
#include "dds/participant_cli.hpp"
#include "dds/result_joiner.hpp"
#include "dds/topics.hpp"
#include "recording.hpp"
#include "report/result_json.hpp"

namespace {
namespace cs = cloudshape;
constexpr const char* kTool = "cloudshape-echo";

std::atomic<bool> g_stop{false};  // the signal flag
void on_signal(int) { g_stop = true; }

std::string status_line(const cs::msg::ServiceStatus& s) {
  nlohmann::ordered_json j;
  j["service"] = s.service();
  j["lane"] = s.lane();
  j["lanes"] = s.lanes();
  j["pid"] = s.pid();
  j["state"] = s.state();
  j["processed"] = s.processed();
  j["errors"] = s.errors();
  j["last_latency_ms"] = s.last_latency_ms();
  return j.dump();
}

long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Takes samples of one topic and hands each to `print` (true when it printed a line) until
// `count` lines, the timeout or a signal; `idle` runs before each wait.
template <class Spec, class Print, class Idle>
int echo(cs::dds::Participant& participant, const Spec& spec, cs::dds::Traffic traffic, long count,
         double timeout_s, Print print, Idle idle) {
  cs::dds::Reader<Spec> reader(participant, spec, traffic);
  typename Spec::Message m;
  long seen = 0;
  const auto start = std::chrono::steady_clock::now();
  while (!g_stop && (count <= 0 || seen < count)) {
    if (timeout_s > 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout_s) {
      if (count > 0) {
        std::fprintf(stderr, "%s: timeout after %g s: %ld of %ld lines\n", kTool, timeout_s, seen, count);
        return 1;
      }
      return 0;
    }
    idle();
    if (!reader.take(m, std::chrono::milliseconds(200))) continue;
    if (print(m)) ++seen;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Prints the cloudshape shape results (one JSON line each) or the services' status.", kTool};
  cs::dds::ParticipantArgs participant_args;
  long count = 0;
  double timeout_s = 0;
  bool status = false;
  bool latency = false;
  std::string record_path;
  bool record_clouds = false;
  cs::dds::add_participant_options(app, participant_args);
  app.add_option("--count", count, "exit after this many samples (exit 1 if --timeout comes first)");
  app.add_option("--timeout", timeout_s, "exit after this many seconds");
  app.add_flag("--status", status, "print the services' status samples instead of results");
  app.add_flag("--latency", latency, "also print each result's inject -> echo latency (and receive time) on stderr");
  app.add_option("--record", record_path,
                 "also write every result to this MCAP file (Detection3DArray and MarkerArray, profile ros2: "
                 "Foxglove and Lichtblick open it); it is complete once echo exits");
  app.add_flag("--record-clouds", record_clouds,
               "with --record: the input clouds too, as sensor_msgs/PointCloud2 (adds a reader on the "
               "raw-cloud topic: start it before cloudshape-inject, which then counts one subscriber more)")
      ->needs("--record");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    cs::dds::Participant participant = cs::dds::open_participant(participant_args, kTool);
    for (const std::string& w : participant.warnings()) std::fprintf(stderr, "%s: warning: %s\n", kTool, w.c_str());
    if (status) {
      return echo(participant, cs::dds::topics::status, cs::dds::Traffic::status, count, timeout_s,
                  [](const cs::msg::ServiceStatus& s) {
                    std::cout << status_line(s) << '\n' << std::flush;
                    return true;
                  },
                  [] {});
    }
    // The solver publishes one result per object: print a cloud once all its objects came,
    // and once only (a cloud sent again after a fault may come back twice).
    cs::dds::ResultJoiner joiner;
    std::optional<cs::echo::EchoRecording> recording;
    std::optional<cs::dds::Reader<decltype(cs::dds::topics::raw_cloud)>> raw_reader;
    if (!record_path.empty()) {
      cs::recording::RecorderSettings settings;
      settings.clouds = record_clouds;
      recording.emplace(record_path, settings);
      if (record_clouds) raw_reader.emplace(participant, cs::dds::topics::raw_cloud, cs::dds::Traffic::data);
    }
    // Input clouds come before their results: take every one waiting before the next result.
    const auto take_clouds = [&] {
      if (!raw_reader) return;
      cs::msg::RawCloud raw;
      while (raw_reader->take(raw, std::chrono::milliseconds(0))) recording->add_cloud(std::move(raw));
    };
    const int exit_status = echo(participant, cs::dds::topics::result, cs::dds::Traffic::data, count, timeout_s,
                [&](cs::msg::ShapeResult& r) {
                  const auto cloud = joiner.add(std::move(r));
                  if (!cloud) return false;
                  const cs::pipeline::RecognitionResult result = cs::dds::to_recognition_result(*cloud);
                  std::cout << cs::report::result_to_json_line(result) << '\n' << std::flush;
                  const cs::msg::CloudHeader& h = cloud->back().header();
                  if (recording) {
                    take_clouds();
                    recording->record(result, h);
                  }
                  if (latency) {
                    // The receive time too, so a steady-rate run can tell the delivered rate.
                    const long long now = now_ns();
                    std::fprintf(stderr, "%s: latency_ms %.3f cloud %llu %s received_ns %lld\n", kTool,
                                 static_cast<double>(now - h.inject_time_ns()) / 1e6,
                                 static_cast<unsigned long long>(h.cloud_id()), h.source().c_str(), now);
                  }
                  return true;
                },
                take_clouds);
    if (recording) {
      recording->close();
      std::fprintf(stderr, "%s: %s: %llu messages recorded\n", kTool, record_path.c_str(),
                   static_cast<unsigned long long>(recording->messages()));
      if (recording->clouds_missed() > 0) {
        std::fprintf(stderr, "%s: %s: %llu result(s) recorded without their cloud (not seen on the raw-cloud topic)\n",
                     kTool, record_path.c_str(), static_cast<unsigned long long>(recording->clouds_missed()));
      }
    }
    if (joiner.duplicates() > 0) {
      std::fprintf(stderr, "%s: dropped %llu duplicate result sample(s)\n", kTool,
                   static_cast<unsigned long long>(joiner.duplicates()));
    }
    return exit_status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", kTool, e.what());
    return 1;
  }
}
