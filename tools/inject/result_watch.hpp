// The thread of cloudshape-inject that watches the result topic and completes a pending
// cloud once all its objects came back.
#pragma once

#include <atomic>
#include <thread>

#include "dds/endpoints.hpp"
#include "dds/result_joiner.hpp"
#include "dds/topics.hpp"
#include "pending_clouds.hpp"

namespace cloudshape::inject {

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
