// What every pipeline service shares: command line, configuration, logging, the stop flag,
// the 1 Hz status topic and the loop take -> lane filter -> stage -> publish.
#pragma once

#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "config/pipeline_config.hpp"
#include "dds/endpoints.hpp"
#include "dds/participant.hpp"
#include "dds/topics.hpp"

namespace cloudshape::service {

struct Options {
  std::string name;            // stage name: ingest, planes, keypoints, classifier, solver
  std::string config_path;     // resolved pipeline.yaml, empty for built-in defaults
  dds::ParticipantArgs participant_args;  // --domain, --security
  std::uint32_t lane = 0;      // this replica's lane
  std::uint32_t lanes = 1;     // replicas of this stage
  int subscribers = 1;         // downstream readers to wait for before reading input
  std::optional<std::size_t> max_points;  // --max-points: overrides input.max_points (ingest)
};

// Parses the common flags; exits the process on --help or a bad command line (status 2).
Options parse_options(int argc, char** argv, const std::string& name, const std::string& about);

// spdlog to stderr, one line per event, tagged with the service and lane.
void set_up_logging(const Options& opt, bool verbose);

// Loads --config or the default pipeline.yaml (built-in defaults when there is none).
config::PipelineConfig load_config(const Options& opt);

// SIGINT / SIGTERM raise the flag; the only global state of a service.
const std::atomic<bool>& install_stop_flag();

// A new header equal to `in` but marking the failure of `stage`.
msg::CloudHeader error_header(const msg::CloudHeader& in, const std::string& stage,
                              const std::string& text);

double elapsed_ms(std::chrono::steady_clock::time_point since);

// Counters and state the status thread publishes once per second.
class StatusReporter {
 public:
  StatusReporter(dds::Participant& participant, const Options& opt);
  ~StatusReporter();
  void set_state(const std::string& state);
  void processed(double latency_ms, bool error);

 private:
  void run();
  dds::Writer<decltype(dds::topics::status)> writer_;
  msg::ServiceStatus status_;
  std::mutex mutex_;
  std::atomic<bool> done_{false};
  std::thread thread_;
};

template <class Out>
std::vector<Out> one(Out&& out) {
  std::vector<Out> v;
  v.push_back(std::move(out));
  return v;
}

// The default on_error: the output carries only the header, marked as failed.
template <class Out, class In>
Out forward_error(In& in, const std::string& stage, const std::string& text) {
  Out out;
  out.header(error_header(in.header(), stage, text));
  return out;
}

// The default for a cloud with no object (header.object_count 0): pass the header on.
template <class Out, class In>
Out forward_empty(In& in) {
  Out out;
  out.header(in.header());
  return out;
}

// Runs a service until stopped. `stage` turns an input sample into output samples (it may
// move from its input; ingest makes one per object). It is not called for samples that
// already carry an error, which go on as `on_error(in, stage_name, text)` makes them, as do
// exceptions thrown by `stage`, nor for a cloud without objects (`on_empty`; without one,
// `stage` gets those too).
template <class InSpec, class OutSpec>
int run(const Options& opt, const InSpec& in_spec, const OutSpec& out_spec,
        const std::function<std::vector<typename OutSpec::Message>(typename InSpec::Message&)>& stage,
        const std::function<typename OutSpec::Message(typename InSpec::Message&, const std::string&,
                                                      const std::string&)>& on_error,
        const std::function<typename OutSpec::Message(typename InSpec::Message&)>& on_empty =
            forward_empty<typename OutSpec::Message, typename InSpec::Message>) {
  using In = typename InSpec::Message;
  using Out = typename OutSpec::Message;
  const std::atomic<bool>& stop = install_stop_flag();
  dds::Participant participant = dds::open_participant(opt.participant_args, "cloudshape-" + opt.name);
  for (const std::string& w : participant.warnings()) spdlog::warn("{}", w);
  StatusReporter status(participant, opt);
  dds::Writer<OutSpec> writer(participant, out_spec);

  // Read input only once someone listens downstream: then "the injector found a subscriber"
  // means the whole chain is up, and no sample is published into the void at start-up.
  status.set_state("waiting");
  spdlog::info("waiting for {} subscriber(s) on {}", opt.subscribers, out_spec.name);
  while (!writer.wait_for_readers(opt.subscribers, std::chrono::seconds(1), &stop)) {
    if (stop) return 0;
  }
  dds::Reader<InSpec> reader(participant, in_spec);
  status.set_state("running");
  spdlog::info("running: {} -> {} on domain {}, lane {}/{}, DDS Security {}", in_spec.name, out_spec.name,
               participant.domain(), opt.lane, opt.lanes, participant.secured() ? "on" : "off");

  In in;
  bool downstream = true;
  while (!stop) {
    // Downstream gone (a stage restarting, a link cut past the lease): leave the input in
    // the upstream queue instead of publishing into the void.
    if (writer.matched_readers() < opt.subscribers) {
      if (downstream) spdlog::warn("no subscriber on {}: input paused", out_spec.name);
      downstream = false;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    if (!downstream) spdlog::info("subscriber back on {}: input resumed", out_spec.name);
    downstream = true;
    if (!reader.take(in, std::chrono::milliseconds(200))) continue;
    const msg::CloudHeader& h = in.header();
    // Replicas split the work on the cloud id: each cloud is handled by exactly one lane.
    if (h.cloud_id() % opt.lanes != opt.lane) continue;
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t id = h.cloud_id();
    const std::string source = h.source();
    const std::uint32_t object = h.object_index();
    std::vector<Out> out;
    bool failed = false;
    if (h.error()) {
      out = one(on_error(in, h.error_stage(), h.error_text()));
      failed = true;
    } else if (h.object_count() == 0 && on_empty) {
      out = one(on_empty(in));
    } else {
      try {
        out = stage(in);
      } catch (const std::exception& e) {
        spdlog::error("cloud {} ({}) object {}: {}", id, source, object, e.what());
        out = one(on_error(in, opt.name, e.what()));
        failed = true;
      }
    }
    bool written = true;
    for (Out& o : out) written = written && writer.write(o, &stop);
    if (!written) break;
    const double ms = elapsed_ms(start);
    status.processed(ms, failed);
    spdlog::info("cloud {} ({}) object {}: {} in {:.2f} ms", id, source, object,
                 failed ? "error passed on" : "done", ms);
  }
  status.set_state("stopping");
  spdlog::info("stopping");
  return 0;
}

}  // namespace cloudshape::service
