// cloudshape-inject's clouds on their way: publishes each on the raw-cloud topic and, until
// its result came back, sends it again whenever that result is overdue (docs/reliability.md
// "No lost clouds").
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dds/endpoints.hpp"
#include "dds/topics.hpp"
#include "geometry/point_cloud.hpp"
#include "pending_clouds.hpp"
#include "result_watch.hpp"

namespace cloudshape::inject {

using RawWriter = dds::Writer<decltype(dds::topics::raw_cloud)>;

// What is published of a file: its points and, for an organized cloud, their pixels.
struct FileCloud {
  PointList points;
  GridLayout grid;
};

// The file's cloud; throws with the problem when it cannot be read or holds no point.
FileCloud read_file_cloud(const std::string& path);
// The cloud of a sent one, read again (from its file, or its recording's message).
FileCloud read_pending_cloud(const PendingCloud& cloud);

struct DeliverySettings {
  int subscribers = 1;           // ingest readers to wait for before each write
  double resend_after_s = 10;    // 0: send once, do not watch results
  double result_timeout_s = 120; // give up after this long without a result
  // Clouds without result before send() waits. inject sets it to the raw-cloud readers'
  // history (Participant::reader_history) unless told otherwise: a reader never holds more
  // than it keeps, so a busy ingest never refuses a 3 MB sample that DDS would send again.
  std::size_t max_pending = 8;
};

class Delivery {
 public:
  using Say = std::function<void(const std::string&)>;
  // Watches the result topic from now on (call once the chain is up for its real consumer).
  Delivery(dds::Participant& participant, RawWriter& writer, const DeliverySettings& settings,
           const std::atomic<bool>& stop, Say say);

  // Sends the overdue clouds again, waits while too many are pending, then publishes `cloud`;
  // false when stopped.
  bool send(const PendingCloud& cloud, const FileCloud& file);

  // Waits for every outstanding result, sending again the overdue ones; returns the ids that
  // still have none (after result_timeout_s without progress, or when stopped).
  std::vector<std::uint64_t> finish();

  // True when a cloud could not be read again to be sent again (its file went away).
  bool lost_a_file() const { return lost_a_file_; }

  // The most clouds that were awaiting their result at once (each cloud counted as it is sent).
  std::size_t most_pending() const { return most_pending_; }
  std::size_t max_pending() const { return settings_.max_pending; }

 private:
  bool tracked() const { return watch_.has_value(); }
  bool resend_overdue();
  bool publish(const PendingCloud& cloud, const FileCloud& file);

  RawWriter& writer_;
  DeliverySettings settings_;
  const std::atomic<bool>& stop_;
  Say say_;
  PendingClouds pending_;
  std::optional<ResultWatch> watch_;
  bool lost_a_file_ = false;
  std::size_t most_pending_ = 0;
};

}  // namespace cloudshape::inject
