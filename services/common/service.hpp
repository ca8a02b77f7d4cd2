// What every pipeline service shares: command line, configuration, logging, the stop flag,
// the 1 Hz status topic and the loop take -> lane filter -> stage -> publish over its inputs.
#pragma once

#include <spdlog/spdlog.h>

#include <fastdds/dds/core/condition/WaitSet.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
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
  std::vector<std::string> ros_topics;    // --ros-topic: PointCloud2 topics read too (ingest)
  std::optional<std::size_t> threads;     // --threads: overrides execution.threads
};

// Parses the common flags; exits the process on --help or a bad command line (status 2).
Options parse_options(int argc, char** argv, const std::string& name, const std::string& about);

// spdlog to stderr, one line per event, tagged with the service and lane.
void set_up_logging(const Options& opt, bool verbose);

// Loads --config or the default pipeline.yaml (built-in defaults when there is none), with
// --threads over its execution.threads, and keeps freed memory as execution.retained_memory_mb says.
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

// The cloud a taken sample is about: what the lane filter and the log line need.
struct CloudRef {
  std::uint64_t cloud_id = 0;
  std::string source;
  std::uint32_t object = 0;
};

// One input of a service: a topic it reads and what it makes of each sample. run() serves the
// stage's own input and further ones (ingest's ROS 2 topics) in one loop, one sample at a time.
template <class Out>
class Input {
 public:
  virtual ~Input() = default;
  virtual std::string topic() const = 0;
  // Triggers while a sample waits (the loop's WaitSet sleeps until one of its inputs has one).
  virtual eprosima::fastdds::dds::Condition& data_available() = 0;
  // Takes the next waiting sample, without waiting: the cloud it is about, nullopt when none.
  virtual std::optional<CloudRef> take() = 0;
  // The output samples of the sample last taken; `failed` set when they carry its failure.
  virtual std::vector<Out> process(bool& failed) = 0;
};

// What a service publishes besides its own topic (the solver's ROS 2 results).
template <class Out>
class SideOutput {
 public:
  virtual ~SideOutput() = default;
  // Their matched readers: they count as downstream subscribers.
  virtual int readers() const = 0;
  // Each output sample once written.
  virtual void published(const Out& out) = 0;
};

// Made once the participant exists and downstream listens (extra inputs) or at once (side output).
template <class Out>
struct Extensions {
  std::function<std::vector<std::unique_ptr<Input<Out>>>(dds::Participant&)> inputs;
  std::function<std::unique_ptr<SideOutput<Out>>(dds::Participant&)> side_output;
};

// A stage's own input: `stage` turns a sample into output samples (it may move from its input;
// ingest makes one per object). It is not called for samples that already carry an error, which
// go on as `on_error(in, stage_name, text)` makes them, as do exceptions thrown by `stage`, nor
// for a cloud without objects (`on_empty`; without one, `stage` gets those too).
template <class InSpec, class OutSpec>
class StageInput : public Input<typename OutSpec::Message> {
 public:
  using In = typename InSpec::Message;
  using Out = typename OutSpec::Message;
  using Stage = std::function<std::vector<Out>(In&)>;
  using OnError = std::function<Out(In&, const std::string&, const std::string&)>;
  using OnEmpty = std::function<Out(In&)>;

  StageInput(dds::Participant& participant, const InSpec& spec, std::string name, Stage stage,
             OnError on_error, OnEmpty on_empty)
      : reader_(participant, spec),
        topic_(spec.name),
        name_(std::move(name)),
        stage_(std::move(stage)),
        on_error_(std::move(on_error)),
        on_empty_(std::move(on_empty)) {}

  std::string topic() const override { return topic_; }
  eprosima::fastdds::dds::Condition& data_available() override { return reader_.data_available(); }

  std::optional<CloudRef> take() override {
    if (!reader_.take(in_, std::chrono::milliseconds(0))) return std::nullopt;
    const msg::CloudHeader& h = in_.header();
    return CloudRef{h.cloud_id(), h.source(), h.object_index()};
  }

  std::vector<Out> process(bool& failed) override {
    const msg::CloudHeader& h = in_.header();
    failed = false;
    if (h.error()) {
      failed = true;
      return one(on_error_(in_, h.error_stage(), h.error_text()));
    }
    if (h.object_count() == 0 && on_empty_) return one(on_empty_(in_));
    try {
      return stage_(in_);
    } catch (const std::exception& e) {
      spdlog::error("cloud {} ({}) object {}: {}", h.cloud_id(), h.source(), h.object_index(), e.what());
      failed = true;
      return one(on_error_(in_, name_, e.what()));
    }
  }

 private:
  dds::Reader<InSpec> reader_;
  std::string topic_;
  std::string name_;
  Stage stage_;
  OnError on_error_;
  OnEmpty on_empty_;
  In in_;
};

// Serves the inputs until stopped, one sample at a time, taking from each in turn: take -> lane
// filter -> process -> publish; input paused while fewer than opt.subscribers listen downstream.
template <class OutSpec>
void serve(const std::vector<std::unique_ptr<Input<typename OutSpec::Message>>>& inputs, const Options& opt,
           const std::atomic<bool>& stop, dds::Writer<OutSpec>& writer,
           SideOutput<typename OutSpec::Message>* side, const std::function<int()>& downstream,
           StatusReporter& status) {
  eprosima::fastdds::dds::WaitSet waitset;
  for (const auto& input : inputs) waitset.attach_condition(input->data_available());
  eprosima::fastdds::dds::ConditionSeq triggered;
  bool listened = true;
  while (!stop) {
    // Downstream gone (a stage restarting, a link cut past the lease): leave the input in
    // the upstream queue instead of publishing into the void.
    if (downstream() < opt.subscribers) {
      if (listened) spdlog::warn("no subscriber on {}: input paused", writer.topic());
      listened = false;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    if (!listened) spdlog::info("subscriber back on {}: input resumed", writer.topic());
    listened = true;
    bool took = false;
    for (const auto& input : inputs) {
      const std::optional<CloudRef> cloud = input->take();
      if (!cloud) continue;
      took = true;
      // Replicas split the work on the cloud id: each cloud is handled by exactly one lane.
      if (cloud->cloud_id % opt.lanes != opt.lane) continue;
      const auto start = std::chrono::steady_clock::now();
      bool failed = false;
      std::vector<typename OutSpec::Message> out = input->process(failed);
      bool written = true;
      for (auto& o : out) {
        written = written && writer.write(o, &stop);
        if (written && side != nullptr) side->published(o);
      }
      if (!written) return;
      const double ms = elapsed_ms(start);
      status.processed(ms, failed);
      spdlog::info("cloud {} ({}) object {}: {} in {:.2f} ms", cloud->cloud_id, cloud->source, cloud->object,
                   failed ? "error passed on" : "done", ms);
    }
    // Taking resets a reader's data-available status: wait only once every input came up empty.
    if (!took) waitset.wait(triggered, eprosima::fastrtps::Duration_t(0, 200'000'000));
  }
}

// Runs a service until stopped: the stage's own input (StageInput) and those of `extensions`,
// all publishing on out_spec.
template <class InSpec, class OutSpec>
int run(const Options& opt, const InSpec& in_spec, const OutSpec& out_spec,
        const typename StageInput<InSpec, OutSpec>::Stage& stage,
        const typename StageInput<InSpec, OutSpec>::OnError& on_error,
        const typename StageInput<InSpec, OutSpec>::OnEmpty& on_empty =
            forward_empty<typename OutSpec::Message, typename InSpec::Message>,
        const Extensions<typename OutSpec::Message>& extensions = {}) {
  using Out = typename OutSpec::Message;
  const std::atomic<bool>& stop = install_stop_flag();
  dds::Participant participant = dds::open_participant(opt.participant_args, "cloudshape-" + opt.name);
  for (const std::string& w : participant.warnings()) spdlog::warn("{}", w);
  StatusReporter status(participant, opt);
  dds::Writer<OutSpec> writer(participant, out_spec);
  std::unique_ptr<SideOutput<Out>> side = extensions.side_output ? extensions.side_output(participant) : nullptr;
  const std::function<int()> downstream = [&] { return writer.matched_readers() + (side ? side->readers() : 0); };

  // Read input only once someone listens downstream: then "the injector found a subscriber"
  // means the whole chain is up, and no sample is published into the void at start-up.
  status.set_state("waiting");
  spdlog::info("waiting for {} subscriber(s) on {}{}", opt.subscribers, out_spec.name,
               side ? " or its ROS 2 topics" : "");
  while (downstream() < opt.subscribers) {
    if (stop) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::vector<std::unique_ptr<Input<Out>>> inputs;
  inputs.push_back(std::make_unique<StageInput<InSpec, OutSpec>>(participant, in_spec, opt.name, stage, on_error,
                                                                 on_empty));
  if (extensions.inputs) {
    for (auto& extra : extensions.inputs(participant)) inputs.push_back(std::move(extra));
  }
  status.set_state("running");
  for (const auto& input : inputs) {
    spdlog::info("running: {} -> {} on domain {}, lane {}/{}, DDS Security {}", input->topic(), out_spec.name,
                 participant.domain(), opt.lane, opt.lanes, participant.secured() ? "on" : "off");
  }
  serve(inputs, opt, stop, writer, side.get(), downstream, status);
  status.set_state("stopping");
  spdlog::info("stopping");
  return 0;
}

}  // namespace cloudshape::service
