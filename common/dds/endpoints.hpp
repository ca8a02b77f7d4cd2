// Typed writer and reader over one topic of topics.hpp: write with back-pressure, take with
// a timeout, and the "is anyone listening" checks the services use to start in order.
#pragma once

#include <atomic>
#include <string>
#include <chrono>
#include <fastdds/dds/core/condition/StatusCondition.hpp>
#include <fastdds/dds/core/status/PublicationMatchedStatus.hpp>
#include <fastdds/dds/core/status/SubscriptionMatchedStatus.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <thread>

#include "dds/participant.hpp"

namespace cloudshape::dds {

template <class Spec>
class Writer {
 public:
  using Message = typename Spec::Message;

  Writer(Participant& p, const Spec& spec, Traffic traffic = Traffic::data)
      : participant_(p), topic_(spec.name), writer_(p.create_writer(p.topic(spec), traffic)) {}
  ~Writer() { participant_.delete_writer(writer_); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // Reliable KEEP_ALL writes block while readers still hold unacknowledged samples
  // (back-pressure); retry until written or `stop` is raised. False only when stopped.
  bool write(Message& m, const std::atomic<bool>* stop = nullptr) {
    while (!writer_->write(&m)) {
      if (stop != nullptr && stop->load()) return false;
    }
    return true;
  }

  const std::string& topic() const { return topic_; }

  int matched_readers() const {
    eprosima::fastdds::dds::PublicationMatchedStatus s;
    writer_->get_publication_matched_status(s);
    return s.current_count;
  }

  // Waits until at least `count` readers matched; false on timeout or stop.
  bool wait_for_readers(int count, std::chrono::milliseconds timeout,
                        const std::atomic<bool>* stop = nullptr) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (matched_readers() < count) {
      if ((stop != nullptr && stop->load()) || std::chrono::steady_clock::now() > deadline) {
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return true;
  }

  // Waits until every reader acknowledged what was written (before exiting a short tool).
  bool wait_for_acknowledgments(std::chrono::milliseconds timeout) {
    const auto s = std::chrono::duration_cast<std::chrono::seconds>(timeout);
    return writer_->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(
               static_cast<std::int32_t>(s.count()), 0)) == ReturnCode_t::RETCODE_OK;
  }

 private:
  Participant& participant_;
  std::string topic_;
  eprosima::fastdds::dds::DataWriter* writer_;
};

template <class Spec>
class Reader {
 public:
  using Message = typename Spec::Message;

  Reader(Participant& p, const Spec& spec, Traffic traffic = Traffic::data)
      : participant_(p), reader_(p.create_reader(p.topic(spec), traffic)) {}
  ~Reader() { participant_.delete_reader(reader_); }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  // Takes the next sample, waiting up to `timeout`; false when none came. `info`, when given,
  // receives the sample's DDS information (writer, sequence number, source timestamp).
  bool take(Message& m, std::chrono::milliseconds timeout,
            eprosima::fastdds::dds::SampleInfo* info_out = nullptr) {
    for (;;) {
      eprosima::fastdds::dds::SampleInfo info;
      if (reader_->take_next_sample(&m, &info) == ReturnCode_t::RETCODE_OK) {
        if (info_out != nullptr) *info_out = info;
        if (info.valid_data) return true;
        continue;  // a lifecycle notice (writer gone), not data
      }
      const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(timeout).count();
      if (!reader_->wait_for_unread_message(eprosima::fastrtps::Duration_t(
              static_cast<std::int32_t>(ns / 1000000000), static_cast<std::uint32_t>(ns % 1000000000)))) {
        return false;
      }
      timeout = std::chrono::milliseconds(0);
    }
  }

  // Triggers while a sample waits to be taken (for a WaitSet over several readers).
  eprosima::fastdds::dds::Condition& data_available() {
    eprosima::fastdds::dds::StatusCondition& c = reader_->get_statuscondition();
    c.set_enabled_statuses(eprosima::fastdds::dds::StatusMask::data_available());
    return c;
  }

  int matched_writers() const {
    eprosima::fastdds::dds::SubscriptionMatchedStatus s;
    reader_->get_subscription_matched_status(s);
    return s.current_count;
  }

 private:
  Participant& participant_;
  eprosima::fastdds::dds::DataReader* reader_;
};

}  // namespace cloudshape::dds
