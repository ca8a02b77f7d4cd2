// The clouds cloudshape-inject sent whose complete result it has not seen yet, and the thread
// that watches the result topic for them: an overdue cloud is sent again, so none is lost.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "dds/endpoints.hpp"
#include "dds/result_joiner.hpp"
#include "dds/topics.hpp"

namespace cloudshape::inject {

using Clock = std::chrono::steady_clock;

struct PendingCloud {
  std::uint64_t id = 0;
  std::string path;            // read again to send it again: memory does not hold the points
  std::string source;          // header.source, with the id the key of its result
  std::int64_t inject_time_ns = 0;  // of the first attempt: latency counts the recovery
  Clock::time_point last_sent;
  int attempts = 0;
};

// Thread-safe: the sender adds and resends, the result watcher completes.
class PendingClouds {
 public:
  void sent(const PendingCloud& cloud) {
    std::lock_guard<std::mutex> lock(mutex_);
    clouds_[cloud.id] = cloud;
  }

  void complete(std::uint64_t id, const std::string& source) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = clouds_.find(id);
    if (it != clouds_.end() && it->second.source == source) clouds_.erase(it);
  }

  // The cloud sent longest ago, if that was at least `after` ago.
  std::optional<PendingCloud> overdue(Clock::time_point now, Clock::duration after) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const PendingCloud* oldest = nullptr;
    for (const auto& [id, c] : clouds_) {
      if (oldest == nullptr || c.last_sent < oldest->last_sent) oldest = &c;
    }
    if (oldest == nullptr || now - oldest->last_sent < after) return std::nullopt;
    return *oldest;
  }

  std::size_t size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return clouds_.size();
  }

  std::vector<std::uint64_t> ids() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::uint64_t> all;
    for (const auto& [id, c] : clouds_) all.push_back(id);
    return all;
  }

 private:
  mutable std::mutex mutex_;
  std::map<std::uint64_t, PendingCloud> clouds_;
};

// Takes every sample of the result topic on its own thread (so the solver is never held up
// by a busy injector) and completes a pending cloud once all its objects came.
class ResultWatch {
 public:
  ResultWatch(dds::Participant& participant, PendingClouds& pending)
      : reader_(participant, dds::topics::result), pending_(pending), thread_([this] { run(); }) {}
  ~ResultWatch() {
    done_ = true;
    thread_.join();
  }
  ResultWatch(const ResultWatch&) = delete;
  ResultWatch& operator=(const ResultWatch&) = delete;

  int matched_writers() const { return reader_.matched_writers(); }

 private:
  void run() {
    msg::ShapeResult result;
    while (!done_) {
      if (!reader_.take(result, std::chrono::milliseconds(100))) continue;
      if (const auto cloud = joiner_.add(std::move(result))) {
        pending_.complete(cloud->front().header().cloud_id(), cloud->front().header().source());
      }
    }
  }

  dds::Reader<decltype(dds::topics::result)> reader_;
  PendingClouds& pending_;
  dds::ResultJoiner joiner_;
  std::atomic<bool> done_{false};
  std::thread thread_;
};

}  // namespace cloudshape::inject
