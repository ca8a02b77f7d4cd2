// The scene benchmark's driver: lists DIR, finds each scene's truth, recognises and scores
// every labelled scene in turn (one frame in memory at a time), then prints the tallies.
#include "scene_bench.hpp"

#include <time.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <random>
#include <unordered_map>

#include "geometry/voxel_grid.hpp"
#include "io/cloud_decimate.hpp"
#include "io/cloud_reader.hpp"
#include "pipeline/recognize.hpp"
#include "scene_report.hpp"
#include "synth/perturb.hpp"

namespace cloudshape::bench {

namespace {

namespace fs = std::filesystem;

// Thrown for any bad input; run_scenes turns it into the one-line message and exit status 2.
struct InputError {
  std::string message;
};

// learn2 before learn10: digit runs compare as numbers.
bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) &&
        std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t ei = i;
      std::size_t ej = j;
      while (ei < a.size() && std::isdigit(static_cast<unsigned char>(a[ei]))) ++ei;
      while (ej < b.size() && std::isdigit(static_cast<unsigned char>(b[ej]))) ++ej;
      const std::string na = a.substr(i, ei - i);
      const std::string nb = b.substr(j, ej - j);
      if (na.size() != nb.size()) return na.size() < nb.size();
      if (na != nb) return na < nb;
      i = ei;
      j = ej;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

std::vector<fs::path> scene_files(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError{"--scenes: " + dir + " is not a directory"};
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".pcd" && entry.is_regular_file()) files.push_back(entry.path());
  }
  if (ec) throw InputError{"--scenes: " + dir + ": cannot be listed (" + ec.message() + ")"};
  if (files.empty()) throw InputError{"--scenes: " + dir + " holds no .pcd file"};
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
    return natural_less(a.filename().string(), b.filename().string());
  });
  return files;
}

struct Scene {
  fs::path path;
  SceneTruth truth;
  std::string truth_source;
};

// A scene's truth: its sidecar (objects it does not list keep the truth file's category
// shapes), else its truth-file entry, else none.
std::optional<Scene> scene_of(const fs::path& path, const std::optional<TruthFile>& file) {
  std::optional<SceneTruth> listed = file ? file->scene(path.filename().string()) : std::nullopt;
  const std::string sidecar = sidecar_path(path.string());
  std::error_code ec;
  if (fs::exists(sidecar, ec)) {
    SceneTruth t = load_sidecar(sidecar, listed ? listed->category : "uncategorized");
    if (listed) t.default_shapes = listed->default_shapes;
    return Scene{path, t, sidecar};
  }
  if (listed) return Scene{path, *listed, file->path};
  return std::nullopt;
}

io::CloudFile read_scene(const fs::path& path) {
  try {
    return io::read_cloud(path.string());
  } catch (const io::ReadError& e) {
    throw InputError{e.what()};
  }
}

double cpu_ms_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

// The centroids of the occupied voxels of edge `size` from `origin` (the points' smallest
// corner), in first-point order, each labelled as most of its points (the smaller label on a
// tie): an unorganized cloud.
io::CloudFile voxel_centroids(const io::CloudFile& cloud, double size, const Point& origin) {
  struct Voxel {
    Point sum = Point::Zero();
    std::size_t count = 0;
    std::map<std::uint32_t, std::size_t> labels;
  };
  std::unordered_map<std::uint64_t, std::size_t> index;
  std::vector<Voxel> voxels;
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    const Eigen::Vector3d c = ((cloud.points[i] - origin) / size).array().floor();
    const auto key = (static_cast<std::uint64_t>(c.x()) << 42) |
                     (static_cast<std::uint64_t>(c.y()) << 21) | static_cast<std::uint64_t>(c.z());
    const auto [at, fresh] = index.emplace(key, voxels.size());
    if (fresh) voxels.emplace_back();
    Voxel& v = voxels[at->second];
    v.sum += cloud.points[i];
    ++v.count;
    ++v.labels[cloud.labels[i]];
  }
  io::CloudFile out;
  out.format = cloud.format;
  for (const Voxel& v : voxels) {
    out.points.push_back(v.sum / static_cast<double>(v.count));
    out.labels.push_back(
        std::max_element(v.labels.begin(), v.labels.end(), [](const auto& a, const auto& b) {
          return a.second < b.second;
        })->first);
  }
  return out;
}

// The scene's cloud, which must carry its labels; on every `decimate`-th pixel and row of its
// grid when that is above 1; without its pixel grid when `unorganized`, downsampled to voxel
// centroids of edge `voxel` when that is positive.
io::CloudFile read_labelled_scene(const Scene& scene, bool unorganized, double voxel,
                                  int decimate) {
  io::CloudFile cloud = read_scene(scene.path);
  if (cloud.labels.empty())
    throw InputError{scene.path.string() +
                     ": no label field, but the truth lists it as a labelled scene"};
  if (decimate > 1) {
    if (!cloud.grid.organized())
      throw InputError{
          scene.path.string() + ": --decimate " + std::to_string(decimate) +
          " needs an organized scene (a PCD of HEIGHT > 1), and this one has no pixel grid"};
    cloud = io::decimated(cloud, static_cast<std::size_t>(decimate));
  }
  if (unorganized) cloud.grid = GridLayout{};
  if (!(voxel > 0.0)) return cloud;
  const geometry::Bounds box = geometry::bounding_box(cloud.points);
  // 21 bits a coordinate for a voxel's key.
  if (!((box.max - box.min).maxCoeff() / voxel < 2.0e6))
    throw InputError{scene.path.string() + ": --voxel " + std::to_string(voxel) +
                     " is too small for its extent"};
  return voxel_centroids(cloud, voxel, box.min);
}

// Every coordinate moved by Gaussian noise of `sigma` (none for a cloud of no spacing).
io::CloudFile jittered(io::CloudFile cloud, double sigma, std::uint64_t seed) {
  if (!(sigma > 0.0)) return cloud;
  std::mt19937_64 rng(seed);
  synth::add_gaussian_noise(cloud.points, sigma, rng);
  return cloud;
}

// One run of the scene's `cloud` (as read or jittered): recognised and scored; `run_label` names
// the run in the per-scene lines.
SceneRun run_scene(const Scene& scene, const io::CloudFile& cloud,
                   const config::PipelineConfig& cfg, parallel::ThreadPool* pool,
                   const std::string& run_label = "") {
  const fs::path& path = scene.path;
  const SceneTruth& truth = scene.truth;
  SceneRun run;
  run.file = path.filename().string() + run_label;
  run.category = truth.category;
  run.truth = scene.truth_source;
  run.points = cloud.points.size();
  run.organized = cloud.grid.organized();
  const double c0 = cpu_ms_now();
  const auto t0 = std::chrono::steady_clock::now();
  const pipeline::RecognitionResult result =
      pipeline::recognize_cloud(cloud.points, cloud.grid, cfg, run.file, pool);
  const auto t1 = std::chrono::steady_clock::now();
  run.cpu_ms = cpu_ms_now() - c0;
  run.wall_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  run.total_ms = result.timings.total_ms;
  std::vector<ReportedObject> reported;
  for (const auto& o : result.objects) {
    reported.push_back(reported_object(o));
    run.reported.push_back({o.shape, o.confidence});
  }
  try {
    run.score = score_scene(cloud.points, cloud.labels, truth, reported);
  } catch (const std::invalid_argument& e) {
    throw InputError{path.string() + ": " + e.what()};
  }
  return run;
}

// "FILE", "FILE, 2 sidecars" or "3 sidecars": where the expected shapes came from.
std::string truth_sources(const std::vector<Scene>& scenes, const std::optional<TruthFile>& file) {
  std::size_t sidecars = 0;
  for (const auto& s : scenes) sidecars += !file || s.truth_source != file->path;
  std::string text = sidecars < scenes.size() ? file->path : "";
  if (sidecars > 0) {
    text += (text.empty() ? "" : ", ") + std::to_string(sidecars) + " sidecar" +
            (sidecars == 1 ? "" : "s");
  }
  return text;
}

int run(const SceneOptions& options, const config::PipelineConfig& cfg) {
  const std::vector<fs::path> files = scene_files(options.dir);
  std::optional<TruthFile> truth_file;
  std::error_code ec;
  if (!options.truth.empty()) {
    truth_file = load_truth_file(options.truth);
  } else if (!options.default_truth.empty() && fs::exists(options.default_truth, ec)) {
    truth_file = load_truth_file(options.default_truth);
  }

  // Every truth is read and every scene without one looked at before the long part starts.
  std::vector<Scene> scenes;
  for (const auto& f : files) {
    if (auto s = scene_of(f, truth_file)) {
      scenes.push_back(*s);
      continue;
    }
    if (read_scene(f).labels.empty()) {
      std::fprintf(stderr, "cloudshape-bench: %s: skipped (no label field)\n", f.string().c_str());
      continue;
    }
    throw InputError{f.string() + ": a labelled scene without truth: no sidecar " +
                     sidecar_path(f.string()) + (truth_file ? ", not in " + truth_file->path : "") +
                     " (give --truth FILE)"};
  }
  if (scenes.empty()) throw InputError{"--scenes: " + options.dir + " holds no labelled scene"};

  const bool progress = isatty(fileno(stderr)) != 0;
  const auto start = std::chrono::steady_clock::now();
  std::vector<SceneRun> runs;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    if (progress)
      std::fprintf(stderr, "\rcloudshape-bench: scene %zu/%zu %-24s", k + 1, scenes.size(),
                   scenes[k].path.filename().string().c_str());
    const io::CloudFile cloud =
        read_labelled_scene(scenes[k], options.unorganized, options.voxel, options.decimate);
    if (!(options.jitter > 0.0)) {
      runs.push_back(run_scene(scenes[k], cloud, cfg, options.pool));
      continue;
    }
    // Jittered runs: every coordinate moved by Gaussian noise of options.jitter of the point
    // spacing (the file's, as read), seeded per scene and run; the file read once.
    const double sigma = options.jitter * geometry::mean_nearest_neighbour_distance(cloud.points);
    for (int r = 0; r < options.jitter_runs; ++r)
      runs.push_back(run_scene(
          scenes[k], jittered(cloud, sigma, 1000003ull * k + static_cast<std::uint64_t>(r)), cfg,
          options.pool, "~" + std::to_string(r + 1)));
  }
  if (progress) std::fprintf(stderr, "\r%70s\r", "");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto rows =
      tally_scenes(runs, truth_file ? truth_file->category_order : std::vector<std::string>{});
  if (options.per_scene) print_scene_lines(runs, stderr);
  if (options.json) {
    nlohmann::ordered_json settings;
    settings["dir"] = options.dir;
    settings["truth"] =
        truth_file ? nlohmann::ordered_json(truth_file->path) : nlohmann::ordered_json(nullptr);
    settings["config"] = options.config_label;
    settings["min_group_points"] = kMinGroupPoints;
    settings["seconds"] = seconds;
    settings["jitter"] = options.jitter;
    settings["jitter_runs"] = options.jitter > 0.0 ? options.jitter_runs : 1;
    settings["unorganized"] = options.unorganized;
    settings["voxel"] = options.voxel;
    settings["decimate"] = options.decimate;
    std::cout << scenes_json(runs, rows, settings).dump(2) << std::endl;
  } else {
    print_scene_table(rows, stdout);
    std::printf("\n%zu scene%s of %s in %.1f s; truth: %s\n", runs.size(),
                runs.size() == 1 ? "" : "s", options.dir.c_str(), seconds,
                truth_sources(scenes, truth_file).c_str());
    if (options.jitter > 0.0)
      std::printf(
          "each scene %d times, its points moved by Gaussian noise of %g of its point spacing "
          "(runs ~1-~%d)\n",
          options.jitter_runs, options.jitter, options.jitter_runs);
  }
  return 0;
}

}  // namespace

int run_scenes(const SceneOptions& options, const config::PipelineConfig& cfg) {
  try {
    return run(options, cfg);
  } catch (const InputError& e) {
    std::fprintf(stderr, "cloudshape-bench: %s\n", e.message.c_str());
  } catch (const TruthError& e) {
    std::fprintf(stderr, "cloudshape-bench: %s\n", e.what());
  }
  return 2;
}

}  // namespace cloudshape::bench
