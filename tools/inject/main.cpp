// cloudshape-inject [--domain N] [--rate HZ] [--loop] [--resend-after S] FILE_OR_DIR...
// Reads clouds with io::read_cloud and publishes each on the raw-cloud topic, once a subscriber
// (the ingest service) is there, then waits for each cloud's result and sends again the clouds
// whose result is overdue (README "No lost clouds"). Reports on stderr.
// Exit: 0, 2 if a file was bad, 1 if no subscriber or a cloud got no result.
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
#include "dds/topics.hpp"
#include "io/cloud_reader.hpp"
#include "io/read_error.hpp"
#include "pending_clouds.hpp"
#include "result_watch.hpp"

namespace {
namespace cs = cloudshape;
namespace fs = std::filesystem;
using cs::inject::Clock;
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

using RawWriter = cs::dds::Writer<decltype(cs::dds::topics::raw_cloud)>;

// The file's points; throws with the problem when it cannot be read or holds none.
cs::PointList read_points(const std::string& path) {
  cs::io::CloudFile cloud;
  try {
    cloud = cs::io::read_cloud(path);
  } catch (const cs::io::ReadError& e) {
    throw std::runtime_error(e.problem().empty() ? std::string(e.what()) : e.problem());
  }
  if (cloud.points.empty()) throw std::runtime_error("no usable points");
  return cloud.points;
}

// Writes one cloud; false when stopped. While ingest is away (killed, restarting) a sample
// would go nowhere, so it waits for the subscribers first.
bool publish(RawWriter& writer, int subscribers, const cs::inject::PendingCloud& c, const cs::PointList& points) {
  while (writer.matched_readers() < subscribers) {
    if (g_stop) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  cs::msg::RawCloud m;
  m.header().cloud_id(c.id);
  m.header().source(c.source);
  m.header().object_index(0);
  m.header().object_count(1);
  m.header().inject_time_ns(c.inject_time_ns);
  m.xyz(cs::dds::to_xyz(points));
  return writer.write(m, &g_stop);
}

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Publishes point-cloud files on the cloudshape raw-cloud topic.", kTool};
  int domain = -1;
  double rate = 0.0;
  bool loop = false;
  double wait_s = 60.0;
  int subscribers = 1;
  std::uint64_t first_id = 0;
  double resend_after_s = 10.0;
  double result_timeout_s = 120.0;
  std::size_t max_pending = 256;
  std::vector<std::string> args;
  app.add_option("--domain", domain, "DDS domain id (default: CLOUDSHAPE_DOMAIN, else 0)");
  app.add_option("--rate", rate, "clouds per second (default: as fast as the pipeline takes them)");
  app.add_flag("--loop", loop, "send the files again and again until interrupted");
  app.add_option("--wait", wait_s, "seconds to wait for a subscriber (default 60)");
  app.add_option("--subscribers", subscribers, "subscribers to wait for (e.g. ingest replicas)");
  app.add_option("--first-id", first_id, "cloud id of the first cloud sent (ids then count up)");
  app.add_option("--resend-after", resend_after_s,
                 "send a cloud again when its result has not come after this many seconds "
                 "(default 10; 0: send once and do not wait for results)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--result-timeout", result_timeout_s,
                 "give up waiting for the outstanding results after this many seconds without one (default 120)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--max-pending", max_pending, "clouds sent but without result before sending waits (default 256)")
      ->check(CLI::PositiveNumber);
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
    cs::dds::Participant participant(cs::dds::resolve_domain(domain >= 0 ? std::optional<int>(domain) : std::nullopt),
                                     kTool);
    RawWriter writer(participant, cs::dds::topics::raw_cloud);
    if (!writer.wait_for_readers(subscribers, std::chrono::milliseconds(static_cast<long>(wait_s * 1000)),
                                 &g_stop)) {
      say("no subscriber on " + std::string(cs::dds::topics::raw_cloud.name) + " after " +
          std::to_string(wait_s) + " s (is cloudshape-ingest running on this domain?)");
      return 1;
    }
    // Results are watched only now: the chain came up for a real consumer (cloudshape-echo),
    // not for this reader, so nothing is published before that consumer listens.
    const bool tracked = resend_after_s > 0;
    const auto resend_after = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(resend_after_s));
    cs::inject::PendingClouds pending;
    std::optional<cs::inject::ResultWatch> watch;
    if (tracked) {
      watch.emplace(participant, pending);
      const auto deadline = Clock::now() + std::chrono::seconds(10);
      while (watch->matched_writers() < 1 && Clock::now() < deadline && !g_stop) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    }
    int status = 0;
    // Sends the overdue clouds again, oldest first; false when stopped.
    const auto resend_overdue = [&] {
      while (const auto c = pending.resend_overdue(Clock::now(), resend_after)) {
        cs::PointList points;
        try {
          points = read_points(c->path);
        } catch (const std::exception& e) {
          say(c->path + ": cannot send cloud " + std::to_string(c->id) + " again: " + e.what());
          pending.complete(c->id, c->source);
          status = 2;
          continue;
        }
        say("no result for cloud " + std::to_string(c->id) + " (" + c->source + ") after " +
            std::to_string(resend_after_s) + " s: sending it again (attempt " + std::to_string(c->attempts) + ")");
        if (!publish(writer, subscribers, *c, points)) return false;
      }
      return true;
    };
    std::uint64_t id = first_id;
    std::size_t sent = 0;
    const auto period = rate > 0 ? std::chrono::duration<double>(1.0 / rate) : std::chrono::duration<double>(0);
    auto next = Clock::now();
    do {
      for (const std::string& path : files) {
        if (g_stop) break;
        while (tracked && pending.size() >= max_pending && resend_overdue() && !g_stop) {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        if (tracked && !resend_overdue()) break;
        cs::PointList points;
        try {
          points = read_points(path);
        } catch (const std::exception& e) {
          say(path + ": " + e.what());
          status = 2;
          continue;
        }
        if (rate > 0) {
          std::this_thread::sleep_until(next);
          next += std::chrono::duration_cast<Clock::duration>(period);
        }
        cs::inject::PendingCloud cloud{id, path, fs::path(path).filename().string(), now_ns(), Clock::now(), 1};
        if (tracked) pending.sent(cloud);
        if (!publish(writer, subscribers, cloud, points)) break;
        say("sent " + path + " as cloud " + std::to_string(id) + " (" + std::to_string(points.size()) + " points)");
        ++id;
        ++sent;
      }
    } while (loop && !g_stop);
    // Every cloud ends in a result: wait for the outstanding ones, sending again the overdue.
    auto progress = Clock::now();
    for (std::size_t left = pending.size(); tracked && left > 0 && !g_stop; left = pending.size()) {
      if (!resend_overdue()) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      if (pending.size() < left) progress = Clock::now();
      if (Clock::now() - progress > std::chrono::duration<double>(result_timeout_s)) break;
    }
    if (tracked && pending.size() > 0) {
      std::string ids;
      for (const std::uint64_t missing : pending.ids()) ids += " " + std::to_string(missing);
      say("no result for " + std::to_string(pending.size()) + " cloud(s):" + ids);
      status = 1;
    }
    // Let the subscribers acknowledge everything before the participant goes away.
    if (!writer.wait_for_acknowledgments(std::chrono::seconds(120))) say("not every cloud was acknowledged");
    say("sent " + std::to_string(sent) + " cloud(s)");
    return status;
  } catch (const std::exception& e) {
    say(e.what());
    return 1;
  }
}
