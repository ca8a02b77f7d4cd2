// cloudshape-inject [--domain N] [--security DIR] [--rate HZ] [--loop | --count N] [--topic NAME]... [--start N|Ts]
//                   [--resend-after S] FILE_OR_DIR...
// Reads clouds with io::read_cloud, and the PointCloud2 messages of .mcap recordings at their
// recorded times, and publishes each on the raw-cloud topic (an organized one with its pixels),
// once a subscriber (the ingest service) is there, then waits for each cloud's result and sends
// again the clouds whose result is overdue (docs/reliability.md "No lost clouds"). Reports on stderr.
// Exit: 0, 2 if a file was bad, 1 if no subscriber or a cloud got no result.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "dds/participant_cli.hpp"
#include "io/mcap_clouds.hpp"
#include "delivery.hpp"
#include "recording.hpp"

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
  return ext == ".pcd" || ext == ".ply" || ext == ".xyz" || ext == ".txt" || ext == ".mcap";
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

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Publishes point-cloud files on the cloudshape raw-cloud topic.", kTool};
  cs::dds::ParticipantArgs participant_args;
  double rate = 0.0;
  bool loop = false;
  double wait_s = 60.0;
  std::uint64_t first_id = 0;
  std::size_t count = 0;
  cs::inject::DeliverySettings delivery_settings;
  std::vector<std::string> args;
  std::vector<std::string> topics;
  cs::dds::add_participant_options(app, participant_args);
  app.add_option("--rate", rate,
                 "clouds per second (default: as fast as the pipeline takes them; a recording at its "
                 "recorded times)");
  app.add_option("--topic", topics,
                 "of .mcap recordings, replay only this PointCloud2 topic (repeat for more; default: all)");
  std::string start_text;
  app.add_option("--start", start_text,
                 "of .mcap recordings, start at this PointCloud2 message (e.g. 150: FILE.mcap#150 first) or "
                 "this long into the recording (e.g. 2.5s), seeking through the file's index");
  app.add_flag("--loop", loop, "send the files again and again until interrupted");
  app.add_option("--count", count, "send this many clouds in all, going round the files (e.g. a steady-rate run)");
  app.add_option("--wait", wait_s, "seconds to wait for a subscriber (default 60)");
  app.add_option("--subscribers", delivery_settings.subscribers, "subscribers to wait for (e.g. ingest replicas)");
  app.add_option("--first-id", first_id, "cloud id of the first cloud sent (ids then count up)");
  app.add_option("--resend-after", delivery_settings.resend_after_s,
                 "send a cloud again when its result has not come after this many seconds "
                 "(default 10; 0: send once and do not wait for results)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--result-timeout", delivery_settings.result_timeout_s,
                 "give up waiting for the outstanding results after this many seconds without one (default 120)")
      ->check(CLI::NonNegativeNumber);
  std::optional<std::size_t> max_pending;
  app.add_option("--max-pending", max_pending,
                 "clouds sent but without result before sending waits (default: the raw-cloud readers' "
                 "history, qos.xml cloudshape_data_reader max_samples: 8)")
      ->check(CLI::PositiveNumber);
  app.add_option("files", args, "cloud files, .mcap recordings, or folders of them")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  cs::inject::ReplaySettings replay{{topics.begin(), topics.end()}, rate <= 0, {}};
  try {
    if (!start_text.empty()) replay.start = cs::io::parse_mcap_start(start_text);
  } catch (const std::invalid_argument& e) {
    say(e.what());
    return 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  const std::vector<std::string> files = expand(args);
  try {
    cs::dds::Participant participant = cs::dds::open_participant(participant_args, kTool);
    for (const std::string& w : participant.warnings()) say("warning: " + w);
    cs::inject::RawWriter writer(participant, cs::dds::topics::raw_cloud);
    // More clouds outstanding than ingest's reader keeps would have a busy ingest refuse whole
    // samples, which reliable DDS sends again and again (docs/dds.md "Back-pressure without resending").
    const std::size_t history = participant.reader_history(cs::dds::Traffic::data);
    delivery_settings.max_pending = max_pending.value_or(history > 0 ? history : delivery_settings.max_pending);
    if (!writer.wait_for_readers(delivery_settings.subscribers, std::chrono::milliseconds(static_cast<long>(wait_s * 1000)),
                                 &g_stop)) {
      say("no subscriber on " + std::string(cs::dds::topics::raw_cloud.name) + " after " +
          std::to_string(wait_s) + " s (is cloudshape-ingest running on this domain?)");
      return 1;
    }
    // Results are watched only now: the chain came up for a real consumer (cloudshape-echo),
    // not for this reader, so nothing is published before that consumer listens.
    cs::inject::Delivery delivery(participant, writer, delivery_settings, g_stop, say);
    int status = 0;
    std::uint64_t id = first_id;
    std::size_t sent = 0;
    const auto period = rate > 0 ? std::chrono::duration<double>(1.0 / rate) : std::chrono::duration<double>(0);
    // Files sent more than once are read once, so reading does not limit a steady rate.
    const bool repeats = loop || count > 0;
    std::map<std::string, cs::inject::FileCloud> read_once;
    const auto started = Clock::now();
    auto next = started;
    // false when stopped.
    const auto send = [&](const std::string& path, std::optional<std::size_t> message, const std::string& source,
                          const cs::inject::FileCloud& file) {
      if (rate > 0) {
        std::this_thread::sleep_until(next);
        next += std::chrono::duration_cast<Clock::duration>(period);
      }
      const cs::inject::PendingCloud cloud{id, path, source, now_ns(), Clock::now(), 1, message};
      if (!delivery.send(cloud, file)) return false;
      const std::string grid = file.grid.organized() ? ", " + std::to_string(file.grid.width) + " x " +
                                                           std::to_string(file.grid.height) + " grid"
                                                     : "";
      say("sent " + source + " as cloud " + std::to_string(id) + " (" + std::to_string(file.points.size()) +
          " points" + grid + ")");
      ++id;
      ++sent;
      return true;
    };
    bool stopped = false;
    do {
      for (const std::string& path : files) {
        if (stopped || g_stop || (count > 0 && sent >= count)) break;
        const std::string name = fs::path(path).filename().string();
        if (cs::io::is_mcap_path(path)) {
          try {
            const cs::inject::ReplayStats stats = cs::inject::replay_recording(
                path, replay, g_stop,
                [&](cs::inject::FileCloud&& file, std::size_t index) {
                  if (count > 0 && sent >= count) return false;
                  stopped = !send(path, index, name + "#" + std::to_string(index), file);
                  return !stopped;
                },
                [&](const cs::io::ReadError& e) {
                  say(e.what());
                  status = 2;
                },
                [&](const std::string& why) {
                  say(path + ": no usable index (" + why + "): read from the start to --start");
                });
            if (stats.clouds == 0) {
              say(path + ": no PointCloud2 message to replay" + (replay.start.at_beginning() ? "" : " from --start"));
            }
            if (replay.recorded_timing && stats.clouds > 0) {
              char late[96];
              std::snprintf(late, sizeof late, ": %zu cloud(s) replayed, at most %.3f s behind the recorded times",
                            stats.clouds, stats.max_late_s);
              say(path + late);
            }
          } catch (const cs::io::ReadError& e) {
            say(e.what());
            status = 2;
          }
          continue;
        }
        cs::inject::FileCloud file;
        try {
          if (const auto found = read_once.find(path); found != read_once.end()) {
            file = found->second;
          } else {
            file = cs::inject::read_file_cloud(path);
            if (repeats) read_once.emplace(path, file);
          }
        } catch (const std::exception& e) {
          say(path + ": " + e.what());
          status = 2;
          continue;
        }
        if (!send(path, std::nullopt, name, file)) stopped = true;
      }
    } while ((loop || (count > 0 && sent < count && sent > 0)) && !g_stop && !stopped);
    const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
    // Every cloud ends in a result: wait for the outstanding ones, sending again the overdue.
    const std::vector<std::uint64_t> missing = delivery.finish();
    if (delivery.lost_a_file()) status = 2;
    if (!missing.empty()) {
      std::string ids;
      for (const std::uint64_t m : missing) ids += " " + std::to_string(m);
      say("no result for " + std::to_string(missing.size()) + " cloud(s):" + ids);
      status = 1;
    }
    // Let the subscribers acknowledge everything before the participant goes away.
    if (!writer.wait_for_acknowledgments(std::chrono::seconds(120))) say("not every cloud was acknowledged");
    char summary[192];
    std::snprintf(summary, sizeof summary, "sent %zu cloud(s) in %.3f s (%.2f clouds/s)", sent, seconds,
                  sent > 1 ? static_cast<double>(sent - 1) / seconds : 0.0);
    std::string line = summary;
    if (delivery_settings.resend_after_s > 0) {
      line += ", at most " + std::to_string(delivery.most_pending()) + " awaiting their result at once (--max-pending " +
              std::to_string(delivery.max_pending()) + ")";
    }
    say(line);
    return status;
  } catch (const std::exception& e) {
    say(e.what());
    return 1;
  }
}
