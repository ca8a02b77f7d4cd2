// cloudshape-echo --record: every result it prints also goes to an MCAP recording, and with
// --record-clouds the input cloud it belongs to (taken from the raw-cloud topic) too.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "cloudshape.h"
#include "pipeline/result.hpp"
#include "recording/result_recorder.hpp"

namespace cloudshape::echo {

class EchoRecording {
public:
  EchoRecording(const std::string& path, recording::RecorderSettings settings);

  // An input cloud seen on the raw-cloud topic, kept until its result comes (the oldest go
  // first beyond a few hundred: a result that never comes must not hold memory for ever).
  void add_cloud(msg::RawCloud&& cloud);
  // Stamped with the cloud's injection time in the configured frame; the cloud too if it was seen.
  void record(const pipeline::RecognitionResult& result, const msg::CloudHeader& header);
  void close() { recorder_.close(); }

  std::uint64_t clouds_missed() const { return clouds_missed_; }
  std::uint64_t messages() const { return recorder_.messages(); }

private:
  recording::RecorderSettings settings_;
  recording::ResultRecorder recorder_;
  std::map<std::pair<std::uint64_t, std::string>, msg::RawCloud> clouds_;  // by cloud id and source
  std::uint64_t clouds_missed_ = 0;
};

}  // namespace cloudshape::echo
