// cloudshape-recognize [--config FILE] [--format json|table] [--pretty] [--verbose] [--render DIR] FILE...
// Runs the whole recognition pipeline in this process and prints one JSON object per input
// file on stdout (JSON Lines; INTERFACE.md), or with --format table a header and one aligned
// line per object for a person. stdout carries nothing else: logs go to stderr.
// --render DIR also writes DIR/<file stem>.png per recognised file (docs/pictures.md).
//
// Exit status: 0 when every file was read and recognised; 2 when a file could not be read or
// held no usable point (one "cloudshape-recognize: <file>: <problem>" line on stderr each, the
// other files still processed), or its picture could not be written (the same one line), or on a
// bad command line, configuration file or --render folder; 1 when the
// recognizer itself failed on a readable file (an internal error, also one stderr line).
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "io/read_error.hpp"
#include "picture_folder.hpp"
#include "pipeline/recognize.hpp"
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

std::string read_error_text(const std::string& path, const cloudshape::io::ReadError& e) {
  std::string text = path;
  if (!e.place().empty()) text += ": " + e.place();
  text += ": " + (e.problem().empty() ? std::string(e.what()) : e.problem());
  return text;
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
      "Recognises the solid shapes in point-cloud files (.pcd, .ply, .xyz, .txt) and "
      "prints one JSON line per file: shape, dimensions, 6-DoF pose, confidence.",
      kTool};
  std::string config_path;
  std::string format = "json";
  bool pretty = false;
  bool verbose = false;
  std::string render_dir;
  std::vector<std::string> files;
  app.add_option("--config", config_path,
                 "pipeline configuration (YAML); default: config/pipeline.yaml of the sources, "
                 "else built-in defaults");
  app.add_option("--format", format,
                 "json: one JSON object per file (the contract, default); table: one line per "
                 "object for a person (file, shape, dimensions, confidence, partial, ms)")
      ->check(CLI::IsMember({"json", "table"}));
  app.add_flag("--pretty", pretty, "indent the JSON (one multi-line object per file)");
  app.add_flag("-v,--verbose", verbose, "debug logging on stderr");
  CLI::Option* render_option = app.add_option("--render", render_dir,
                 "also write one PNG per file into DIR (created if missing): the points, each "
                 "solid's wireframe and label, from the sensor's or principal axes' view and an "
                 "oblique one");
  app.add_option("files", files, "point-cloud files")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitBadInput;
  }

  set_up_logging(verbose);
  const bool table = format == "table";
  cs::report::TableLayout layout;
  if (table) {
    std::vector<std::string> sources;
    for (const auto& f : files) sources.push_back(std::filesystem::path(f).filename().string());
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
  int status = 0;
  if (table) std::cout << cs::report::table_header(layout) << '\n';
  for (const std::string& path : files) {
    cs::io::CloudFile cloud;
    try {
      cloud = cs::io::read_cloud(path, limits);
    } catch (const cs::io::ReadError& e) {
      report_failure(read_error_text(path, e));
      status = kExitBadInput;
      continue;
    } catch (const std::exception& e) {
      report_failure(path + ": " + e.what());
      status = kExitBadInput;
      continue;
    }
    if (cloud.points.empty()) {
      report_failure(path + ": no usable points" +
                     (cloud.non_finite_dropped > 0
                          ? " (" + std::to_string(cloud.non_finite_dropped) +
                                " points read, all with NaN or infinite coordinates)"
                          : " (the file holds no points)"));
      status = kExitBadInput;
      continue;
    }
    if (const std::size_t far = cs::first_point_beyond(cloud.points, cfg.input.max_coordinate);
        far < cloud.points.size()) {
      std::ostringstream text;
      text << path << ": a point at (" << cloud.points[far].transpose()
           << "), beyond input.max_coordinate " << cfg.input.max_coordinate;
      report_failure(text.str());
      status = kExitBadInput;
      continue;
    }
    if (cloud.non_finite_dropped > 0) {
      spdlog::info("{}: dropped {} points with NaN or infinite coordinates", path,
                   cloud.non_finite_dropped);
    }
    spdlog::debug("{}: {} points ({})", path, cloud.points.size(), cloud.format);

    const std::string source = std::filesystem::path(path).filename().string();
    try {
      const cs::pipeline::RecognitionResult result =
          cs::pipeline::recognize_cloud(cloud.points, cloud.grid, cfg, source);
      if (table) {
        for (const std::string& row : cs::report::table_rows(result, layout))
          std::cout << row << '\n';
      } else {
        std::cout << (pretty ? cs::report::result_to_json_pretty(result)
                             : cs::report::result_to_json_line(result))
                  << '\n';
      }
      std::cout << std::flush;
      if (pictures) {
        const std::filesystem::path png = pictures->path_for(source);
        try {
          cs::render::write_picture_png(cloud.points, cloud.grid, result, png.string());
        } catch (const std::exception& e) {
          report_failure(path + ": no picture: " + e.what());
          status = kExitBadInput;
        }
      }
    } catch (const std::exception& e) {
      report_failure(path + ": recognition failed: " + e.what());
      if (status == 0) status = kExitInternal;
    }
  }
  return status;
}
