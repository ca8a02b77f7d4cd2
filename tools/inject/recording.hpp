// cloudshape-inject's replay of an MCAP recording: its PointCloud2 messages, decoded as the
// ROS 2 input decodes them, handed over one by one at their recorded times.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <set>
#include <string>

#include "delivery.hpp"
#include "io/mcap_clouds.hpp"
#include "io/read_error.hpp"

namespace cloudshape::inject {

struct ReplaySettings {
  std::set<std::string> topics;  // empty: every PointCloud2 channel
  bool recorded_timing = true;   // false: as fast as `send` returns (the caller paces)
  io::McapCloudStart start;      // --start: where each replay of the file begins
};

struct ReplayStats {
  std::size_t clouds = 0;
  double max_late_s = 0;  // the most a cloud went out after its recorded time
  std::uint64_t chunks_skipped = 0;  // with a start: chunks not read
};

// `send` gets each cloud with its message index and returns false to stop the replay.
// A message that does not decode goes to `on_bad`, and the replay goes on; with a start, why
// the file has no usable index goes to `on_unindexed` before it is read from its start. Throws io::ReadError
// for a damaged recording, after every cloud before the damage was sent.
ReplayStats replay_recording(const std::string& path, const ReplaySettings& settings, const std::atomic<bool>& stop,
                             const std::function<bool(FileCloud&&, std::size_t index)>& send,
                             const std::function<void(const io::ReadError&)>& on_bad,
                             const std::function<void(const std::string&)>& on_unindexed);

// Message `index` of the recording again, to send it a second time; throws like read_file_cloud.
FileCloud read_recorded_cloud(const std::string& path, std::size_t index);

}  // namespace cloudshape::inject
