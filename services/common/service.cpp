#include "common/service.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <cstdlib>

#include "dds/participant_cli.hpp"
#include "parallel/retained_memory.hpp"

namespace cloudshape::service {
namespace {

std::atomic<bool> g_stop{false};  // the signal flag

void on_signal(int) { g_stop = true; }

}  // namespace

Options parse_options(int argc, char** argv, const std::string& name, const std::string& about) {
  Options opt;
  opt.name = name;
  CLI::App app{about, "cloudshape-" + name};
  bool verbose = false;
  app.add_option("--config", opt.config_path, "pipeline configuration (YAML); default: config/pipeline.yaml");
  dds::add_participant_options(app, opt.participant_args);
  app.add_option("--lane", opt.lane, "this replica's lane, 0..lanes-1 (handles cloud_id % lanes == lane)");
  app.add_option("--lanes", opt.lanes, "number of replicas of this stage")->check(CLI::PositiveNumber);
  app.add_option("--subscribers", opt.subscribers,
                 "downstream readers to wait for before reading input (e.g. the next stage's replicas)")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-points", opt.max_points, "largest raw cloud accepted (ingest; default input.max_points)");
  app.add_option("--ros-topic", opt.ros_topics,
                 "also read sensor_msgs/PointCloud2 on this ROS 2 topic, e.g. /camera/depth/points "
                 "(ingest; repeatable; beside ros2.input_topics)");
  app.add_option("--threads", opt.threads,
                 "threads of the stage, this one included (default: execution.threads, 0 = one per core); "
                 "the same results for any count");
  app.add_flag("-v,--verbose", verbose, "debug logging");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e) == 0 ? 0 : 2);
  }
  if (opt.lane >= opt.lanes) {
    std::fprintf(stderr, "cloudshape-%s: --lane %u must be below --lanes %u\n", name.c_str(),
                 opt.lane, opt.lanes);
    std::exit(2);
  }
  set_up_logging(opt, verbose);
  return opt;
}

void set_up_logging(const Options& opt, bool verbose) {
  std::string tag = opt.name;
  if (opt.lanes > 1) tag += "[" + std::to_string(opt.lane) + "]";
  auto logger = spdlog::stderr_color_mt(tag);
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("%Y-%m-%d %H:%M:%S.%e %n [%l] %v");
  spdlog::set_level(verbose ? spdlog::level::debug : spdlog::level::info);
  spdlog::flush_on(spdlog::level::info);
}

config::PipelineConfig load_config(const Options& opt) {
  std::string path = opt.config_path.empty() ? config::default_pipeline_config_path() : opt.config_path;
  if (path.empty()) {
    spdlog::info("configuration: built-in defaults");
    config::PipelineConfig cfg;
    if (opt.threads) cfg.execution.threads = static_cast<std::int64_t>(*opt.threads);
    parallel::retain_freed_memory(cfg.execution.retained_memory_mb);
    return cfg;
  }
  spdlog::info("configuration: {}", path);
  config::PipelineConfig cfg = config::load_pipeline_config(path);
  if (opt.threads) cfg.execution.threads = static_cast<std::int64_t>(*opt.threads);
  parallel::retain_freed_memory(cfg.execution.retained_memory_mb);
  return cfg;
}

const std::atomic<bool>& install_stop_flag() {
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  return g_stop;
}

msg::CloudHeader error_header(const msg::CloudHeader& in, const std::string& stage,
                              const std::string& text) {
  msg::CloudHeader h = in;
  h.error(true);
  h.error_stage(stage);
  h.error_text(text);
  return h;
}

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

StatusReporter::StatusReporter(dds::Participant& participant, const Options& opt)
    : writer_(participant, dds::topics::status, dds::Traffic::status) {
  status_.service(opt.name);
  status_.lane(opt.lane);
  status_.lanes(opt.lanes);
  status_.pid(static_cast<std::int32_t>(::getpid()));
  status_.state("starting");
  thread_ = std::thread([this] { run(); });
}

StatusReporter::~StatusReporter() {
  done_ = true;
  thread_.join();
  // One last status so watchers see the clean stop.
  std::lock_guard<std::mutex> lock(mutex_);
  status_.state("stopped");
  writer_.write(status_);
}

void StatusReporter::set_state(const std::string& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  status_.state(state);
}

void StatusReporter::processed(double latency_ms, bool error) {
  std::lock_guard<std::mutex> lock(mutex_);
  status_.processed(status_.processed() + 1);
  if (error) status_.errors(status_.errors() + 1);
  status_.last_latency_ms(latency_ms);
}

void StatusReporter::run() {
  auto next = std::chrono::steady_clock::now();
  while (!done_) {
    if (std::chrono::steady_clock::now() >= next) {
      msg::ServiceStatus copy;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        copy = status_;
      }
      writer_.write(copy);
      next += std::chrono::seconds(1);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

}  // namespace cloudshape::service
