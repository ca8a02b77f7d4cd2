// cloudshape-bench: how long each recognition stage takes, per shape and cloud size.
//
//   cloudshape-bench [--sizes 10000,100000,1000000] [--shapes box,cone,...] [--reps R]
//                    [--warmup W] [--seed S] [--noise SIGMA] [--config FILE] [--threads N] [--json]
//   cloudshape-bench --accuracy [--count N] [--max-points P] [--conditions clean,noise,...]
//                    [--seed S] [--config FILE] [--json] [--per-cloud] [--save-clouds DIR]
//                    (how right it is: see accuracy.hpp)
//   cloudshape-bench --scenes DIR [--truth FILE] [--json] [--per-scene] [--config FILE]
//                    [--jitter SHARE [--jitter-runs R]] [--unorganized] [--voxel SIZE]
//                    (labelled real or synthetic scenes: see scene_bench.hpp)
//   cloudshape-bench --pool [--threads N] [--json]
//                    (what a parallel run costs on the thread pool: see pool_bench.hpp)
//
// For every (shape, size) one synthetic solid is drawn (speed_shapes.hpp: the six by
// synth::random_solid, a prism and a frustum as meshes; fixed seed) and its surface sampled --
// outside the timed region -- then recognize_cloud runs W untimed warm-up times and R timed times.
// Reported per stage: median and p10-p90 (plus min/max in --json) of the StageTimings the
// pipeline returns, and of the wall clock around the whole call as a cross-check of `total`.
// Progress goes to stderr; the table or JSON to stdout.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "accuracy.hpp"
#include "bench_stats.hpp"
#include "config/pipeline_config.hpp"
#include "parallel/retained_memory.hpp"
#include "parallel/thread_pool.hpp"
#include "pipeline/recognize.hpp"
#include "pool_bench.hpp"
#include "scene_bench.hpp"
#include "speed_shapes.hpp"
#include "synth/ground_truth.hpp"
#include "synth/perturb.hpp"

namespace {

namespace cs = cloudshape;
using cs::bench::Summary;

const std::vector<std::string> kColumns = {"preprocess", "planes", "keypoints", "classify",
                                           "solve",      "total",  "wall"};

struct Case {
  std::string shape;
  std::size_t points = 0;
  int reps = 0;
  std::map<std::string, int> recognized;  // first object's shape -> how many timed runs
  std::map<std::string, std::vector<double>> samples;
  std::map<std::string, Summary> summary;
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) parts.push_back(item);
  }
  return parts;
}

std::string recognized_label(const Case& c) {
  std::string label;
  for (const auto& [shape, n] : c.recognized) {
    if (!label.empty()) label += ",";
    label += shape + (n == c.reps ? "" : ":" + std::to_string(n));
  }
  return label;
}

void print_table(const std::vector<Case>& cases) {
  std::printf("%-17s %9s %5s %-17s %-7s", "shape", "points", "reps", "recognized", "ms");
  for (const auto& col : kColumns) std::printf(" %14s", col.c_str());
  std::printf("\n");
  for (const auto& c : cases) {
    std::printf("%-17s %9zu %5d %-17s %-7s", c.shape.c_str(), c.points, c.reps,
                recognized_label(c).c_str(), "median");
    for (const auto& col : kColumns) std::printf(" %14.2f", c.summary.at(col).median);
    std::printf("\n%-17s %9s %5s %-17s %-7s", "", "", "", "", "p10-p90");
    for (const auto& col : kColumns) {
      char range[64];
      std::snprintf(range, sizeof range, "%.2f-%.2f", c.summary.at(col).p10, c.summary.at(col).p90);
      std::printf(" %14s", range);
    }
    std::printf("\n");
  }
}

void print_json(const std::vector<Case>& cases, const nlohmann::ordered_json& settings) {
  nlohmann::ordered_json out;
  out["settings"] = settings;
  out["cases"] = nlohmann::ordered_json::array();
  for (const auto& c : cases) {
    nlohmann::ordered_json j;
    j["shape"] = c.shape;
    j["points"] = c.points;
    j["reps"] = c.reps;
    j["recognized"] = c.recognized;
    nlohmann::ordered_json ms;
    for (const auto& col : kColumns) {
      const Summary& s = c.summary.at(col);
      ms[col] = {
          {"median", s.median}, {"p10", s.p10}, {"p90", s.p90}, {"min", s.min}, {"max", s.max}};
    }
    j["timings_ms"] = ms;
    out["cases"].push_back(j);
  }
  std::cout << out.dump(2) << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Per-stage timings (median, p10-p90) of the recognition pipeline on synthetic "
      "solids.",
      "cloudshape-bench"};
  std::string sizes_arg = "10000,100000,1000000";
  std::string shapes_arg;
  int reps_arg = 0;
  int warmup = 1;
  std::uint64_t seed = 42;
  double size = 100.0;
  double noise = 0.0;
  std::string config_path;
  bool json = false;
  bool accuracy = false;
  int count = 30;
  std::size_t max_points = 200000;
  std::string conditions_arg;
  bool per_cloud = false;
  std::string save_dir;
  int threads = -1;
  app.add_option("--sizes", sizes_arg, "comma-separated point counts")->capture_default_str();
  app.add_option("--shapes", shapes_arg,
                 "comma-separated subset of box,tetrahedron,pentagonal_prism,cone,cylinder,sphere "
                 "(default: these six), and prism (an L-profile), frustum");
  app.add_option("--reps", reps_arg,
                 "timed repetitions per case (default 15 up to 100k points, 5 above)");
  app.add_option("--warmup", warmup, "untimed runs before the timed ones")->capture_default_str();
  app.add_option("--seed", seed, "seed of the solids and their sampling")->capture_default_str();
  app.add_option("--solid-size", size, "largest extent of each solid")->capture_default_str();
  app.add_option("--noise", noise, "Gaussian noise sigma, as a fraction of --solid-size")
      ->capture_default_str();
  app.add_option("--config", config_path,
                 "pipeline configuration (default: config/pipeline.yaml, else built-in)");
  app.add_flag("--json", json, "machine-readable output");
  app.add_option("--threads", threads,
                 "threads of the recognition, this one included (default: execution.threads of the "
                 "configuration, 0 = one per core); the answers are the same for any count")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--accuracy", accuracy,
               "measure recognition accuracy instead of timings (clean, noise, outliers, "
               "density, single_view, table_view, multi, real, negatives, new_shapes, new_shapes_view)");
  app.add_option("--count", count, "--accuracy: clouds per shape per condition")
      ->capture_default_str();
  app.add_option("--max-points", max_points,
                 "--accuracy: cap on a synthetic cloud's points (clouds drawn above it get it)")
      ->capture_default_str();
  app.add_option("--conditions", conditions_arg,
                 "--accuracy: comma-separated subset of "
                 "clean,noise,outliers,density,single_view,table_view,multi,real,negatives,new_shapes,new_shapes_view");
  app.add_flag("--per-cloud", per_cloud,
               "--accuracy: one line per cloud on stderr (truths, results, how it was made)");
  app.add_option("--save-clouds", save_dir,
                 "--accuracy: also write every cloud to DIR/<condition>-<shape>-<i>.pcd (DIR is made if missing)");
  cs::bench::SceneOptions scenes;
  app.add_option("--scenes", scenes.dir,
                 "score the labelled scenes (.pcd with a label field) in DIR instead")
      ->excludes("--accuracy");
  app.add_option("--truth", scenes.truth,
                 "--scenes: expected shapes per scene (default: the mOSD learn truth for the "
                 "scenes it lists; <scene>.truth.json sidecars override)");
  app.add_flag("--per-scene", scenes.per_scene, "--scenes: one line per scene on stderr");
  app.add_option(
         "--jitter", scenes.jitter,
         "--scenes: score each scene --jitter-runs times, its points moved by Gaussian noise of "
         "this share of its point spacing (e.g. 0.05): far below a sensor's noise, answers that "
         "change are on a decision's edge")
      ->check(CLI::Range(0.0, 10.0));
  app.add_option("--jitter-runs", scenes.jitter_runs, "--scenes --jitter: runs per scene")
      ->default_val(3)
      ->check(CLI::Range(1, 100));
  app.add_flag(
      "--unorganized", scenes.unorganized,
      "--scenes: drop each scene's pixel grid first (the same points unorganized, as a PLY "
      "or XYZ export of the frame has them)");
  app.add_option(
         "--voxel", scenes.voxel,
         "--scenes: downsample each scene to voxel centroids of this size first (each labelled as "
         "most of its points; unorganized), as a pipeline often thins a frame")
      ->check(CLI::PositiveNumber);
  app.add_option(
         "--decimate", scenes.decimate,
         "--scenes: keep every N-th pixel of every N-th row of each organized scene (its grid "
         "N times smaller each way: 2 makes 320 x 240 of 640 x 480), as a camera run at a "
         "lower resolution gives")
      ->check(CLI::Range(1, 16));
  bool pool_bench = false;
  app.add_flag(
         "--pool", pool_bench,
         "time the thread pool's runs (blocks of none to about a millisecond) against the same "
         "blocks in order")
      ->excludes("--accuracy")
      ->excludes("--scenes");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  std::vector<std::size_t> sizes;
  for (const auto& s : split(sizes_arg)) {
    try {
      std::size_t used = 0;
      const unsigned long long n = std::stoull(s, &used);
      if (used != s.size() || n == 0) throw std::invalid_argument(s);
      sizes.push_back(static_cast<std::size_t>(n));
    } catch (const std::exception&) {
      std::fprintf(stderr, "cloudshape-bench: --sizes: '%s' is not a point count\n", s.c_str());
      return 2;
    }
  }
  std::vector<std::string> shape_names;
  if (shapes_arg.empty()) {
    for (const auto kind : cs::synth::all_shape_kinds()) shape_names.push_back(cs::synth::to_string(kind));
  } else {
    shape_names = split(shapes_arg);
  }
  if (sizes.empty() || shape_names.empty() || reps_arg < 0 || warmup < 0 || size <= 0 || noise < 0) {
    std::fprintf(stderr, "cloudshape-bench: nothing to run (check the arguments)\n");
    return 2;
  }

  cs::config::PipelineConfig cfg;
  if (config_path.empty()) config_path = cs::config::default_pipeline_config_path();
  try {
    if (!config_path.empty()) cfg = cs::config::load_pipeline_config(config_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cloudshape-bench: %s\n", e.what());
    return 2;
  }
  if (threads >= 0) cfg.execution.threads = threads;
  // Cloud after cloud (and stage after stage of one), freed buffers are kept for the next, as
  // in the services.
  cs::parallel::retain_freed_memory(cfg.execution.retained_memory_mb);
  cs::parallel::ThreadPool pool(static_cast<std::size_t>(cfg.execution.threads));
  if (accuracy) {
    if (count <= 0 || max_points == 0) {
      std::fprintf(stderr, "cloudshape-bench: --count and --max-points must be positive\n");
      return 2;
    }
    if (!save_dir.empty()) {
      // Made before the first cloud so that a bad path fails at once, not after the run.
      std::error_code ec;
      std::filesystem::create_directories(save_dir, ec);
      if (ec || !std::filesystem::is_directory(save_dir)) {
        std::fprintf(stderr, "cloudshape-bench: --save-clouds: '%s' cannot be made a directory: %s\n",
                     save_dir.c_str(), ec ? ec.message().c_str() : "a file of that name exists");
        return 2;
      }
    }
    cs::bench::AccuracyOptions options;
    options.suite.count = count;
    options.suite.seed = seed;
    options.suite.max_points = max_points;
    options.suite.shared_data_dir = CLOUDSHAPE_SHARED_DATA_DIR;
    options.conditions = split(conditions_arg);
    options.json = json;
    options.per_cloud = per_cloud;
    options.save_dir = save_dir;
    options.config_label = config_path.empty() ? "built-in defaults" : config_path;
    options.pool = &pool;
    return cs::bench::run_accuracy(options, cfg);
  }
  if (pool_bench) {
    cs::bench::PoolBenchOptions options;
    options.pool = &pool;
    options.json = json;
    return cs::bench::run_pool_bench(options);
  }
  if (!scenes.dir.empty()) {
    scenes.default_truth = CLOUDSHAPE_SCENE_TRUTH;
    scenes.json = json;
    scenes.config_label = config_path.empty() ? "built-in defaults" : config_path;
    scenes.pool = &pool;
    return cs::bench::run_scenes(scenes, cfg);
  }

  std::vector<cs::bench::SpeedShape> kinds;
  for (const auto& name : shape_names) {
    auto shape = cs::bench::speed_shape(name, size, seed);
    if (!shape) {
      std::fprintf(stderr, "cloudshape-bench: --shapes: unknown shape '%s'\n", name.c_str());
      return 2;
    }
    kinds.push_back(std::move(*shape));
  }
  // Progress only on a terminal: redirected output stays the table alone.
  const bool progress = isatty(fileno(stderr)) != 0;
  std::vector<Case> cases;
  for (const std::size_t n : sizes) {
    for (std::size_t k = 0; k < kinds.size(); ++k) {
      Case c;
      c.shape = kinds[k].name;
      c.points = n;
      c.reps = reps_arg > 0 ? reps_arg : (n <= 100000 ? 15 : 5);

      // Untimed: the solid (same for every size of a shape) and its sampling.
      std::mt19937_64 sample_rng(seed ^ (n * 0x9E3779B97F4A7C15ull));
      cs::PointList cloud = kinds[k].sample(n, sample_rng);
      if (noise > 0) cs::synth::add_gaussian_noise(cloud, noise * size, sample_rng);
      const std::string source = c.shape + "-" + std::to_string(n);

      for (int i = 0; i < warmup + c.reps; ++i) {
        if (progress)
          std::fprintf(stderr, "\rcloudshape-bench: %-17s %9zu points  %s %d/%d   ", c.shape.c_str(),
                       n, i < warmup ? "warm-up" : "rep    ", i < warmup ? i + 1 : i - warmup + 1,
                       i < warmup ? warmup : c.reps);
        const auto t0 = std::chrono::steady_clock::now();
        const cs::pipeline::RecognitionResult r = cs::pipeline::recognize_cloud(cloud, cfg, source, &pool);
        const auto t1 = std::chrono::steady_clock::now();
        if (i < warmup) continue;
        const auto& t = r.timings;
        c.samples["preprocess"].push_back(t.preprocess_ms);
        c.samples["planes"].push_back(t.planes_ms);
        c.samples["keypoints"].push_back(t.keypoints_ms);
        c.samples["classify"].push_back(t.classify_ms);
        c.samples["solve"].push_back(t.solve_ms);
        c.samples["total"].push_back(t.total_ms);
        c.samples["wall"].push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        ++c.recognized[r.objects.empty() ? "none" : r.objects.front().shape];
      }
      for (const auto& col : kColumns) c.summary[col] = cs::bench::summarize(c.samples[col]);
      cases.push_back(std::move(c));
    }
  }
  if (progress) std::fprintf(stderr, "\r%80s\r", "");

  if (json) {
    nlohmann::ordered_json settings;
    settings["seed"] = seed;
    settings["solid_size"] = size;
    settings["noise"] = noise;
    settings["warmup"] = warmup;
    settings["threads"] = pool.size();
    settings["config"] = config_path.empty() ? "built-in defaults" : config_path;
    print_json(cases, settings);
  } else {
    std::printf("threads: %zu\n", pool.size());
    print_table(cases);
  }
  return 0;
}
