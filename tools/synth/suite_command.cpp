// `suite`: K random clouds of every shape, each with its ground truth, for batch evaluation.
#include "arguments.hpp"
#include "cloud_output.hpp"
#include "commands.hpp"
#include "synth/ground_truth_json.hpp"
#include "synth/random_solid.hpp"
#include "synth/synthetic_cloud.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>

namespace cloudshape::synth_tool {

namespace {

struct SuiteArgs {
  std::string out;
  std::size_t points = 20000;
  std::uint64_t seed = 1;
  std::size_t count = 5;
  double size = 30.0;
  double noise = 0.0;
  double outliers = 0.0;
  bool partial = false;
  std::string format = "pcd";
  std::string pcd_encoding = "binary";
};

// A camera 3 sizes from the solid's centre in a uniformly random direction.
Eigen::Vector3d random_camera(const synth::SolidSpec& spec, double size, std::mt19937_64& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  Eigen::Vector3d direction;
  do {
    direction = {gauss(rng), gauss(rng), gauss(rng)};
  } while (direction.norm() < 1e-9);
  return spec.pose.center + 3.0 * size * direction.normalized();
}

void run_suite(const SuiteArgs& args) {
  const auto encoding = parse_pcd_encoding(args.pcd_encoding);
  check_output_path("x." + args.format);
  std::error_code error;
  std::filesystem::create_directories(args.out, error);
  if (error) throw std::runtime_error(args.out + ": cannot create directory: " + error.message());

  std::mt19937_64 rng(args.seed);
  std::size_t written = 0;
  for (synth::ShapeKind kind : synth::all_shape_kinds()) {
    for (std::size_t i = 0; i < args.count; ++i) {
      const synth::SolidSpec spec = synth::random_solid(kind, rng, args.size);
      synth::CloudOptions options;
      options.points = args.points;
      options.noise_sigma = args.noise * args.size;
      options.outlier_fraction = args.outliers;
      if (args.partial) options.view = random_camera(spec, args.size, rng);
      const std::uint64_t cloud_seed = rng();
      const auto cloud = synth::make_synthetic_cloud({spec}, options, cloud_seed);

      char stem[64];
      std::snprintf(stem, sizeof stem, "%s_%03zu", synth::to_string(kind).c_str(), i);
      const std::string name = std::string(stem) + "." + args.format;
      const std::string path = (std::filesystem::path(args.out) / name).string();
      write_cloud(path, cloud.points, encoding);
      auto doc = synth::ground_truth_json(name, cloud.objects, cloud.info);
      doc["suite"] = {{"seed", args.seed}, {"index", i}};
      write_json(ground_truth_path(path), doc);
      ++written;
    }
  }
  std::cerr << "cloudshape-synth: wrote " << written << " clouds to " << args.out << '\n';
}

}  // namespace

void add_suite_command(CLI::App& app) {
  auto args = std::make_shared<SuiteArgs>();
  CLI::App* cmd = app.add_subcommand(
      "suite", "COUNT random clouds of each shape into DIR (box_000.pcd + box_000.json, ...).");
  cmd->add_option("--out", args->out, "Output directory (created if missing)")->required();
  cmd->add_option("--points", args->points, "Surface points per cloud")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed of the whole suite")->capture_default_str();
  cmd->add_option("--count", args->count, "Clouds per shape")->capture_default_str();
  cmd->add_option("--size", args->size, "Largest extent of every solid")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--noise", args->noise, "Gaussian noise sigma as a fraction of the size")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--outliers", args->outliers, "Outliers as a fraction of the points")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--partial", args->partial,
                "Single view: keep what a camera 3 sizes away in a random direction sees");
  cmd->add_option("--format", args->format, "pcd, ply or xyz")
      ->capture_default_str()
      ->check(CLI::IsMember({"pcd", "ply", "xyz"}));
  cmd->add_option("--pcd-encoding", args->pcd_encoding, "ascii, binary or binary_compressed")
      ->capture_default_str();
  cmd->callback([args] { run_suite(*args); });
}

}  // namespace cloudshape::synth_tool
