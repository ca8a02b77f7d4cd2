// The clouds cloudshape-inject sent whose complete result it has not seen yet: an overdue
// cloud is sent again, so none is lost (docs/reliability.md "No lost clouds").
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace cloudshape::inject {

using Clock = std::chrono::steady_clock;

struct PendingCloud {
  std::uint64_t id = 0;
  std::string path;            // read again to send it again: memory does not hold the points
  std::string source;          // header.source, with the id the key of its result
  std::int64_t inject_time_ns = 0;  // of the first attempt: latency counts the recovery
  Clock::time_point last_sent;
  int attempts = 0;
  std::optional<std::size_t> message;  // the PointCloud2 message of an .mcap path
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
    if (it != clouds_.end() && it->second.source == source) {
      clouds_.erase(it);
      completed_.notify_all();
    }
  }

  // Waits until fewer than `limit` clouds are pending or `timeout` passed; true when fewer.
  bool wait_below(std::size_t limit, Clock::duration timeout) const {
    std::unique_lock<std::mutex> lock(mutex_);
    return completed_.wait_for(lock, timeout, [&] { return clouds_.size() < limit; });
  }

  // The cloud sent longest ago, if that was at least `after` ago, marked as sent again now
  // (in one step: a result that completes it meanwhile must not be undone by the resend).
  std::optional<PendingCloud> resend_overdue(Clock::time_point now, Clock::duration after) {
    std::lock_guard<std::mutex> lock(mutex_);
    PendingCloud* oldest = nullptr;
    for (auto& [id, c] : clouds_) {
      if (oldest == nullptr || c.last_sent < oldest->last_sent) oldest = &c;
    }
    if (oldest == nullptr || now - oldest->last_sent < after) return std::nullopt;
    oldest->last_sent = now;
    ++oldest->attempts;
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
  mutable std::condition_variable completed_;
  std::map<std::uint64_t, PendingCloud> clouds_;
};

}  // namespace cloudshape::inject
