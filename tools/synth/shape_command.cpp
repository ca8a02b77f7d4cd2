// `shape`: one solid with given dimensions, optionally posed, viewed and degraded.
#include "arguments.hpp"
#include "cloud_output.hpp"
#include "commands.hpp"
#include "mesh_shape.hpp"
#include "synth/ground_truth_json.hpp"
#include "synth/pose.hpp"
#include "synth/synthetic_cloud.hpp"

#include <filesystem>
#include <memory>
#include <random>
#include <stdexcept>

namespace cloudshape::synth_tool {

namespace {

struct ShapeArgs {
  std::string shape;
  std::string dims;
  std::string section;
  std::size_t points = 20000;
  std::uint64_t seed = 1;
  bool random_pose = false;
  double noise = 0.0;
  double outliers = 0.0;
  std::string view;
  std::string density_from;
  double patchy = 0.0;
  std::string output;
  std::string pcd_encoding = "binary";
};

void run_shape(const ShapeArgs& args) {
  check_output_path(args.output);
  if (is_mesh_shape(args.shape)) {
    if (args.outliers > 0.0 || !args.density_from.empty() || args.patchy > 0.0)
      throw std::invalid_argument("--shape " + args.shape + ": --outliers, --density-from and --patchy are not supported");
    MeshShapeRequest request;
    request.shape = args.shape;
    request.values = parse_numbers(args.dims, "--dims");
    request.section = args.section;
    request.random_pose = args.random_pose;
    request.points = args.points;
    request.noise = args.noise;
    if (!args.view.empty()) request.view = parse_point(args.view, "--view");
    request.seed = args.seed;
    run_mesh_shape(request, args.output, args.pcd_encoding);
    return;
  }
  const auto encoding = parse_pcd_encoding(args.pcd_encoding);
  const auto kind = synth::shape_kind_from_string(args.shape);
  if (!kind) throw std::invalid_argument("--shape: unknown shape '" + args.shape + "'");
  const auto values = parse_numbers(args.dims, "--dims");

  synth::Pose pose;
  if (args.random_pose) {
    // The size is needed for the offset, so validate the dimensions once without a pose first.
    const double size = synth::characteristic_size(synth::make_solid(*kind, values));
    // A separate stream keeps the pose from sharing random numbers with the sampling.
    std::seed_seq pose_seed{args.seed, std::uint64_t{0x706f7365}};
    std::mt19937_64 pose_rng(pose_seed);
    pose = synth::random_pose(pose_rng, size);
  }
  synth::SolidSpec spec;
  try {
    spec = synth::make_solid(*kind, values, pose);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--dims: ") + e.what());
  }

  synth::CloudOptions options;
  options.points = args.points;
  options.noise_sigma = args.noise * synth::characteristic_size(spec);
  options.outlier_fraction = args.outliers;
  if (!args.view.empty()) options.view = parse_point(args.view, "--view");
  if (!args.density_from.empty())
    options.density.falloff_from = parse_point(args.density_from, "--density-from");
  options.density.patchiness = args.patchy;

  const auto cloud = synth::make_synthetic_cloud({spec}, options, args.seed);
  write_cloud(args.output, cloud.points, encoding);
  const std::string source = std::filesystem::path(args.output).filename().string();
  write_json(ground_truth_path(args.output),
             synth::ground_truth_json(source, cloud.objects, cloud.info));
}

}  // namespace

void add_shape_command(CLI::App& app) {
  auto args = std::make_shared<ShapeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "shape", "Sample one solid; writes OUT and its ground truth OUT.json (same stem).");
  cmd->add_option("--shape", args->shape,
                  "box, tetrahedron, pentagonal_prism, cone, cylinder, sphere, frustum, prism")
      ->required();
  cmd->add_option("--dims", args->dims,
                  "Comma-separated, INTERFACE.md order: box L,W,H; tetrahedron EDGE; "
                  "pentagonal_prism SIDE,HEIGHT; cone/cylinder RADIUS,HEIGHT; sphere RADIUS; "
                  "frustum RADIUS,TOP_RADIUS,HEIGHT; prism WIDTH,HEIGHT")
      ->required();
  cmd->add_option("--section", args->section,
                  "prism cross-section: triangle, rhombus, regular_hexagon, hexagon, convex, letter_l, "
                  "letter_t, plus, star (default: drawn by --seed)");
  cmd->add_option("--points", args->points, "Surface points (before outliers)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed")->capture_default_str();
  cmd->add_flag("--random-pose", args->random_pose,
                "Uniformly random rotation and a centre within +-size of the origin");
  cmd->add_option("--noise", args->noise,
                  "Gaussian noise sigma as a fraction of the size (largest extent)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--outliers", args->outliers, "Outliers to add, as a fraction of the points")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--view", args->view, "Camera X,Y,Z: keep only what it sees");
  cmd->add_option("--density-from", args->density_from,
                  "X,Y,Z: point density falls with the squared distance from here (a camera)");
  cmd->add_option("--patchy", args->patchy,
                  "0..1: share of the points lost at the centre of 6 random patches")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("-o,--output", args->output, "Output cloud (.pcd, .ply, .xyz)")->required();
  cmd->add_option("--pcd-encoding", args->pcd_encoding, "ascii, binary or binary_compressed")
      ->capture_default_str();
  cmd->callback([args] { run_shape(*args); });
}

}  // namespace cloudshape::synth_tool
