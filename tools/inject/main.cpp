// cloudshape-inject [--domain N] [--security DIR] [--rate HZ] [--loop] FILE_OR_DIR...
// Reads clouds with io::read_cloud and publishes each on the raw-cloud topic, once a subscriber
// (the ingest service) is there. Reports on stderr. Exit: 0, 2 if a file was bad, 1 if no subscriber.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "dds/convert.hpp"
#include "dds/endpoints.hpp"
#include "dds/security.hpp"
#include "dds/topics.hpp"
#include "io/cloud_reader.hpp"
#include "io/read_error.hpp"

namespace {
namespace cs = cloudshape;
namespace fs = std::filesystem;
constexpr const char* kTool = "cloudshape-inject";

std::atomic<bool> g_stop{false};  // the signal flag
void on_signal(int) { g_stop = true; }

void say(const std::string& text) { std::fprintf(stderr, "%s: %s\n", kTool, text.c_str()); }

bool is_cloud_file(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".pcd" || ext == ".ply" || ext == ".xyz" || ext == ".txt";
}

// Files as given; folders contribute their cloud files, sorted by name.
std::vector<std::string> expand(const std::vector<std::string>& args) {
  std::vector<std::string> files;
  for (const std::string& a : args) {
    std::error_code ec;
    if (fs::is_directory(a, ec)) {
      std::vector<std::string> inside;
      for (const auto& e : fs::directory_iterator(a, ec)) {
        if (e.is_regular_file() && is_cloud_file(e.path())) inside.push_back(e.path().string());
      }
      std::sort(inside.begin(), inside.end());
      files.insert(files.end(), inside.begin(), inside.end());
    } else {
      files.push_back(a);
    }
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Publishes point-cloud files on the cloudshape raw-cloud topic.", kTool};
  int domain = -1;
  std::string security;
  double rate = 0.0;
  bool loop = false;
  double wait_s = 60.0;
  int subscribers = 1;
  std::uint64_t first_id = 0;
  std::vector<std::string> args;
  app.add_option("--domain", domain, "DDS domain id (default: CLOUDSHAPE_DOMAIN, else 0)");
  app.add_option("--security", security,
                 "DDS Security folder made by tools/make-certs.sh (default: CLOUDSHAPE_SECURITY_DIR; empty: off)");
  app.add_option("--rate", rate, "clouds per second (default: as fast as the pipeline takes them)");
  app.add_flag("--loop", loop, "send the files again and again until interrupted");
  app.add_option("--wait", wait_s, "seconds to wait for a subscriber (default 60)");
  app.add_option("--subscribers", subscribers, "subscribers to wait for (e.g. ingest replicas)");
  app.add_option("--first-id", first_id, "cloud id of the first cloud sent (ids then count up)");
  app.add_option("files", args, "cloud files or folders of them")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  const std::vector<std::string> files = expand(args);
  try {
    cs::dds::Participant participant(
        cs::dds::resolve_domain(domain >= 0 ? std::optional<int>(domain) : std::nullopt), kTool,
        cs::dds::resolve_security_dir(app.count("--security") > 0 ? std::optional<std::string>(security)
                                                                  : std::nullopt));
    cs::dds::Writer<decltype(cs::dds::topics::raw_cloud)> writer(participant, cs::dds::topics::raw_cloud);
    if (!writer.wait_for_readers(subscribers, std::chrono::milliseconds(static_cast<long>(wait_s * 1000)),
                                 &g_stop)) {
      say("no subscriber on " + std::string(cs::dds::topics::raw_cloud.name) + " after " +
          std::to_string(wait_s) + " s (is cloudshape-ingest running on this domain?)");
      return 1;
    }
    int status = 0;
    std::uint64_t id = first_id;
    std::size_t sent = 0;
    const auto period = rate > 0 ? std::chrono::duration<double>(1.0 / rate) : std::chrono::duration<double>(0);
    auto next = std::chrono::steady_clock::now();
    do {
      for (const std::string& path : files) {
        if (g_stop) break;
        cs::io::CloudFile cloud;
        try {
          cloud = cs::io::read_cloud(path);
          if (cloud.points.empty()) throw std::runtime_error("no usable points");
        } catch (const cs::io::ReadError& e) {
          say(path + ": " + (e.problem().empty() ? std::string(e.what()) : e.problem()));
          status = 2;
          continue;
        } catch (const std::exception& e) {
          say(path + ": " + e.what());
          status = 2;
          continue;
        }
        if (rate > 0) {
          std::this_thread::sleep_until(next);
          next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(period);
        }
        cs::msg::RawCloud m;
        m.header().cloud_id(id);
        m.header().source(fs::path(path).filename().string());
        m.header().object_index(0);
        m.header().object_count(1);
        m.header().inject_time_ns(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                      std::chrono::system_clock::now().time_since_epoch())
                                      .count());
        m.xyz(cs::dds::to_xyz(cloud.points));
        if (!writer.write(m, &g_stop)) break;
        say("sent " + path + " as cloud " + std::to_string(id) + " (" + std::to_string(cloud.points.size()) +
            " points)");
        ++id;
        ++sent;
      }
    } while (loop && !g_stop);
    // Let the subscribers acknowledge everything before the participant goes away.
    if (!writer.wait_for_acknowledgments(std::chrono::seconds(120))) say("not every cloud was acknowledged");
    say("sent " + std::to_string(sent) + " cloud(s)");
    return status;
  } catch (const std::exception& e) {
    say(e.what());
    return 1;
  }
}
