// cloudshape-recognize [--config FILE] [--format json|table] [--pretty] [--verbose]
//                      [--render DIR] [--record OUT.mcap [--record-clouds]] [--start N|Ts] FILE...
// Runs the whole recognition pipeline in this process and prints one JSON object per input
// file, or per PointCloud2 message of a .mcap recording, on stdout (JSON Lines; INTERFACE.md),
// or with --format table a header and one aligned line per object for a person. stdout
// carries nothing else: logs go to stderr. --render DIR also writes DIR/<source>.png per
// recognised cloud (docs/pictures.md).
//
// Exit status: 0 when every file was read and recognised; 2 when a file could not be read or
// held no usable point (one "cloudshape-recognize: <file>: <problem>" line on stderr each, the
// other files still processed), or on a bad command line or configuration file; 1 when the
// recognizer itself failed on a readable file (an internal error, also one stderr line).
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cloud_inputs.hpp"
#include "config/pipeline_config.hpp"
#include "io/pointcloud2_encode.hpp"
#include "parallel/retained_memory.hpp"
#include "picture_folder.hpp"
#include "pipeline/recognize.hpp"
#include "recording/result_recorder.hpp"
#include "render/picture_png.hpp"
#include "report/result_json.hpp"
#include "report/result_table.hpp"

namespace {

constexpr const char* kTool = "cloudshape-recognize";
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;

// The one line a user sees for a file that failed; never more than one line.
void report_failure(const std::string& text) {
  std::string line = text;
  for (char& c : line) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  std::cout.flush();
  std::fprintf(stderr, "%s: %s\n", kTool, line.c_str());
  std::fflush(stderr);
}

// A recording's cloud keeps its own header, time and topic; a file's gets the current time
// in the configured frame, and its points as a PointCloud2 of the usual camera layout.
void record(cloudshape::recording::ResultRecorder& recorder, const cloudshape::pipeline::RecognitionResult& result,
            const cloudshape::recognize::InputCloud& in, const cloudshape::config::PipelineConfig& cfg) {
  namespace cs = cloudshape;
  if (in.recorded != nullptr) {
    recorder.record(result, in.recorded->header, in.recorded->log_time, &in.recorded->message, in.recorded->topic);
    return;
  }
  const auto now = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  const cs::io::RosHeader header = cs::recording::file_header(now, cfg.ros2);
  if (!recorder.records_clouds()) {
    recorder.record(result, header, now);
    return;
  }
  const cs::io::PointCloud2 cloud = cs::io::encode_pointcloud2(in.cloud.points, in.cloud.grid, {}, header);
  recorder.record(result, header, now, &cloud);
}

void set_up_logging(bool verbose) {
  // stdout is reserved for results, so every log line (the pipeline's too) goes to stderr.
  auto logger = spdlog::stderr_color_mt(kTool);
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("%n: [%l] %v");
  spdlog::set_level(verbose ? spdlog::level::debug : spdlog::level::warn);
}

}  // namespace

int main(int argc, char** argv) {
  namespace cs = cloudshape;

  CLI::App app{
      "Recognises the solid shapes in point-cloud files (.pcd, .ply, .xyz, .txt) and recordings "
      "(.mcap: every sensor_msgs/msg/PointCloud2 message) and prints one JSON line per cloud: "
      "shape, dimensions, 6-DoF pose, confidence.",
      kTool};
  std::string config_path;
  std::string format = "json";
  bool pretty = false;
  bool verbose = false;
  std::vector<std::string> files;
  std::string record_path;
  bool record_clouds = false;
  int threads = -1;
  app.add_option("--config", config_path,
                 "pipeline configuration (YAML); default: config/pipeline.yaml of the sources, "
                 "else built-in defaults");
  app.add_option("--format", format,
                 "json: one JSON object per file (the contract, default); table: one line per "
                 "object for a person (file, shape, dimensions, confidence, partial, ms)")
      ->check(CLI::IsMember({"json", "table"}));
  app.add_flag("--pretty", pretty, "indent the JSON (one multi-line object per file)");
  app.add_option("--threads", threads,
                 "threads of the recognition, this one included (default: execution.threads of the "
                 "configuration, 0 = one per core); the answers are the same for any count")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("-v,--verbose", verbose, "debug logging on stderr");
  std::string render_dir;
  CLI::Option* render_option = app.add_option("--render", render_dir,
                 "also write one PNG per cloud into DIR (created if missing): the points, each "
                 "solid's wireframe and label, from the sensor's or principal axes' view and an "
                 "oblique one");
  app.add_option("--record", record_path,
                 "also write the results to this MCAP file (Detection3DArray and MarkerArray per cloud, "
                 "profile ros2: Foxglove and Lichtblick open it)");
  app.add_flag("--record-clouds", record_clouds, "with --record: the input clouds too, as sensor_msgs/PointCloud2")
      ->needs("--record");
  std::string start_text;
  app.add_option("--start", start_text,
                 "of .mcap recordings, start at this PointCloud2 message (e.g. 150: FILE.mcap#150 first) or "
                 "this long into the recording (e.g. 2.5s), seeking through the file's index");
  app.add_option("files", files, "point-cloud files and MCAP recordings")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }

  set_up_logging(verbose);
  cs::io::McapCloudStart start;
  try {
    if (!start_text.empty()) start = cs::io::parse_mcap_start(start_text);
  } catch (const std::invalid_argument& e) {
    report_failure(e.what());
    return kExitBadInput;
  }
  const bool table = format == "table";
  cs::report::TableLayout layout;
  if (table) {
    std::vector<std::string> sources;
    for (const auto& f : files) {
      // A recording's clouds are named FILE#INDEX: room for indexes up to 5 digits.
      std::string name = std::filesystem::path(f).filename().string();
      if (std::filesystem::path(f).extension() == ".mcap") name += "#00000";
      sources.push_back(name);
    }
    layout = cs::report::table_layout(sources);
  }

  cs::config::PipelineConfig cfg;
  if (config_path.empty()) config_path = cs::config::default_pipeline_config_path();
  if (config_path.empty()) {
    spdlog::debug("no configuration file found: using built-in defaults");
  } else {
    try {
      cfg = cs::config::load_pipeline_config(config_path);
      spdlog::debug("configuration: {}", config_path);
    } catch (const std::exception& e) {
      report_failure(e.what());
      return kExitBadInput;
    }
  }

  if (threads >= 0) cfg.execution.threads = threads;
  // Cloud after cloud (and stage after stage of one), freed buffers are kept for the next, as
  // in the services.
  cs::parallel::retain_freed_memory(cfg.execution.retained_memory_mb);
  cs::parallel::ThreadPool pool(static_cast<std::size_t>(cfg.execution.threads));
  spdlog::debug("recognition threads: {}", pool.size());

  std::optional<cs::tools::PictureFolder> pictures;
  if (render_option->count() > 0) {
    try {
      pictures.emplace(render_dir);
    } catch (const std::exception& e) {
      report_failure(e.what());
      return kExitBadInput;
    }
  }

  // The configuration's input limits: a bigger file is refused before it is read in full.
  const cs::io::ReadLimits limits{static_cast<std::size_t>(cfg.input.max_points),
                                  static_cast<std::size_t>(cfg.input.max_bytes)};
  std::optional<cs::recording::ResultRecorder> recorder;
  if (!record_path.empty()) {
    try {
      recorder.emplace(record_path, cs::recording::RecorderSettings{record_clouds, cs::io::McapCompression::zstd,
                                                                    cfg.ros2, "/cloudshape/points"});
    } catch (const std::exception& e) {
      report_failure(e.what());
      return kExitBadInput;
    }
  }
  int status = 0;
  const auto fail = [&](const std::string& text) {
    report_failure(text);
    status = kExitBadInput;
  };
  if (table) std::cout << cs::report::table_header(layout) << '\n';
  for (const std::string& path : files) {
    cs::recognize::for_each_input_cloud(
        path, limits, start, [&](const std::string& note) { spdlog::warn("{}", note); },
        [&](cs::recognize::InputCloud& in) {
          const cs::io::CloudFile& cloud = in.cloud;
          if (cloud.points.empty()) {
            fail(in.where + ": no usable points" +
                 (cloud.non_finite_dropped > 0
                      ? " (" + std::to_string(cloud.non_finite_dropped) +
                            " points read, all with NaN or infinite coordinates)"
                      : " (the file holds no points)"));
            return;
          }
          if (const std::size_t far = cs::first_point_beyond(cloud.points, cfg.input.max_coordinate);
              far < cloud.points.size()) {
            std::ostringstream text;
            text << in.where << ": a point at (" << cloud.points[far].transpose()
                 << "), beyond input.max_coordinate " << cfg.input.max_coordinate;
            fail(text.str());
            return;
          }
          if (cloud.non_finite_dropped > 0) {
            spdlog::info("{}: dropped {} points with NaN or infinite coordinates", in.where,
                         cloud.non_finite_dropped);
          }
          spdlog::debug("{}: {} points ({})", in.where, cloud.points.size(), cloud.format);
          try {
            const cs::pipeline::RecognitionResult result =
                cs::pipeline::recognize_cloud(cloud.points, cloud.grid, cfg, in.source, &pool);
            if (table) {
              for (const std::string& row : cs::report::table_rows(result, layout))
                std::cout << row << '\n';
            } else {
              std::cout << (pretty ? cs::report::result_to_json_pretty(result)
                                   : cs::report::result_to_json_line(result))
                        << '\n';
            }
            std::cout << std::flush;
            if (recorder) record(*recorder, result, in, cfg);
            if (pictures) {
              const std::filesystem::path png = pictures->path_for(in.source);
              try {
                cs::render::write_picture_png(cloud.points, cloud.grid, result, png.string());
              } catch (const std::exception& e) {
                fail(in.where + ": no picture: " + e.what());
              }
            }
          } catch (const std::exception& e) {
            report_failure(in.where + ": recognition failed: " + e.what());
            if (status == 0) status = kExitInternal;
          }
        },
        fail);
  }
  if (recorder) {
    try {
      recorder->close();
      spdlog::info("{}: {} messages recorded", record_path, recorder->messages());
    } catch (const std::exception& e) {
      report_failure(e.what());
      return kExitInternal;
    }
  }
  return status;
}
