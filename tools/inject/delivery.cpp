// cloudshape-inject's delivery: a file's cloud (points and, organized, their pixels) published on the
// raw-cloud topic, and sent again while its result is overdue.
#include "delivery.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "dds/convert.hpp"
#include "io/cloud_reader.hpp"
#include "io/read_error.hpp"
#include "recording.hpp"

namespace cloudshape::inject {

FileCloud read_file_cloud(const std::string& path) {
  io::CloudFile cloud;
  try {
    cloud = io::read_cloud(path);
  } catch (const io::ReadError& e) {
    throw std::runtime_error(e.problem().empty() ? std::string(e.what()) : e.problem());
  }
  if (cloud.points.empty()) throw std::runtime_error("no usable points");
  return FileCloud{std::move(cloud.points), std::move(cloud.grid)};
}

FileCloud read_pending_cloud(const PendingCloud& cloud) {
  return cloud.message ? read_recorded_cloud(cloud.path, *cloud.message) : read_file_cloud(cloud.path);
}

Delivery::Delivery(dds::Participant& participant, RawWriter& writer, const DeliverySettings& settings,
                   const std::atomic<bool>& stop, Say say)
    : writer_(writer), settings_(settings), stop_(stop), say_(std::move(say)) {
  if (settings_.resend_after_s <= 0) return;
  watch_.emplace(participant, pending_);
  // The solver's writer is usually matched within milliseconds; a result missed before that
  // would only make its cloud be sent again.
  const auto deadline = Clock::now() + std::chrono::seconds(10);
  while (watch_->matched_writers() < 1 && Clock::now() < deadline && !stop_) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

bool Delivery::send(const PendingCloud& cloud, const FileCloud& file) {
  if (tracked()) {
    // Woken by the result that makes room, so the wait adds no polling delay to the replay.
    while (!pending_.wait_below(settings_.max_pending, std::chrono::milliseconds(100)) && !stop_) {
      if (!resend_overdue()) return false;
    }
    if (!resend_overdue()) return false;
    pending_.sent(cloud);  // before the write: its result may come back at once
    most_pending_ = std::max(most_pending_, pending_.size());
  }
  return publish(cloud, file);
}

std::vector<std::uint64_t> Delivery::finish() {
  auto progress = Clock::now();
  for (std::size_t left = pending_.size(); tracked() && left > 0 && !stop_; left = pending_.size()) {
    if (!resend_overdue()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (pending_.size() < left) progress = Clock::now();
    if (Clock::now() - progress > std::chrono::duration<double>(settings_.result_timeout_s)) break;
  }
  return pending_.ids();
}

// Oldest first; false when stopped.
bool Delivery::resend_overdue() {
  const auto after = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(settings_.resend_after_s));
  while (const auto c = pending_.resend_overdue(Clock::now(), after)) {
    FileCloud file;
    try {
      file = read_pending_cloud(*c);
    } catch (const std::exception& e) {
      say_(c->path + ": cannot send cloud " + std::to_string(c->id) + " again: " + e.what());
      pending_.complete(c->id, c->source);
      lost_a_file_ = true;
      continue;
    }
    say_("no result for cloud " + std::to_string(c->id) + " (" + c->source + ") after " +
         std::to_string(settings_.resend_after_s) + " s: sending it again (attempt " + std::to_string(c->attempts) + ")");
    if (!publish(*c, file)) return false;
  }
  return true;
}

// While ingest is away (killed, restarting) a sample would go nowhere: wait for it first.
bool Delivery::publish(const PendingCloud& c, const FileCloud& file) {
  while (writer_.matched_readers() < settings_.subscribers) {
    if (stop_) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  msg::RawCloud m = dds::to_raw_cloud(file.points, file.grid);
  m.header().cloud_id(c.id);
  m.header().source(c.source);
  m.header().object_index(0);
  m.header().object_count(1);
  m.header().inject_time_ns(c.inject_time_ns);
  return writer_.write(m, &stop_);
}

}  // namespace cloudshape::inject
