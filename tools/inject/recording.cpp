// cloudshape-inject's replay of an MCAP recording: its PointCloud2 messages, decoded as the
// ROS 2 input decodes them, handed over one by one at their recorded times.
#include "recording.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <thread>

#include "io/mcap_clouds.hpp"

namespace cloudshape::inject {
namespace {

// Unwinds the reader when `send` asks to stop: nothing after it is read.
struct Stopped {};

// Sleeps until `when` in short steps, so an interrupt is honoured within 0.1 s.
void sleep_until(Clock::time_point when, const std::atomic<bool>& stop) {
  while (!stop && Clock::now() < when) {
    std::this_thread::sleep_until(std::min(when, Clock::now() + std::chrono::milliseconds(100)));
  }
}

}  // namespace

ReplayStats replay_recording(const std::string& path, const ReplaySettings& settings, const std::atomic<bool>& stop,
                             const std::function<bool(FileCloud&&, std::size_t index)>& send,
                             const std::function<void(const io::ReadError&)>& on_bad,
                             const std::function<void(const std::string&)>& on_unindexed) {
  ReplayStats stats;
  std::optional<std::uint64_t> first_log_time;
  Clock::time_point started;
  const io::McapCloudHandlers handlers{
      [&](io::McapCloud&& message) {
        if (stop) throw Stopped{};
        if (message.cloud.points.empty()) {
          on_bad(io::ReadError(path, "message " + std::to_string(message.index) + " (" + message.topic + ")",
                               "no usable points"));
          return;
        }
        if (settings.recorded_timing) {
          if (!first_log_time) {
            first_log_time = message.log_time;
            started = Clock::now();
          }
          // Out-of-order times (a recording merged from several) go out at once.
          const auto offset = std::chrono::nanoseconds(
              message.log_time > *first_log_time ? message.log_time - *first_log_time : 0);
          const auto due = started + std::chrono::duration_cast<Clock::duration>(offset);
          sleep_until(due, stop);
          stats.max_late_s = std::max(stats.max_late_s, std::chrono::duration<double>(Clock::now() - due).count());
        }
        if (stop || !send(FileCloud{std::move(message.cloud.points), std::move(message.cloud.grid)}, message.index)) {
          throw Stopped{};
        }
        ++stats.clouds;
      },
      on_bad};
  io::McapCloudStart start = settings.start;
  start.on_unindexed = on_unindexed;
  try {
    const io::McapReadSummary read = io::read_mcap_clouds(path, settings.topics, handlers, {}, start);
    stats.chunks_skipped = read.chunks_skipped;
  } catch (const Stopped&) {
  }
  return stats;
}

FileCloud read_recorded_cloud(const std::string& path, std::size_t index) {
  io::McapCloud message;
  try {
    message = io::read_mcap_cloud_at(path, index);
  } catch (const io::ReadError& e) {
    throw std::runtime_error(e.place() + ": " + e.problem());
  }
  if (message.cloud.points.empty()) throw std::runtime_error("no usable points");
  return FileCloud{std::move(message.cloud.points), std::move(message.cloud.grid)};
}

}  // namespace cloudshape::inject
