// `mesh`: area-weighted sampling of a mesh file (e.g. a YCB scan), optionally single-view.
#include "arguments.hpp"
#include "cloud_output.hpp"
#include "commands.hpp"
#include "io/mesh_reader.hpp"
#include "synth/mesh_sampling.hpp"
#include "synth/mesh_visibility.hpp"
#include "synth/perturb.hpp"
#include "synth/visibility.hpp"

#include <memory>
#include <optional>
#include <random>
#include <stdexcept>

namespace cloudshape::synth_tool {

namespace {

struct MeshArgs {
  std::string file;
  std::size_t points = 0;
  std::string view;
  double noise = 0.0;
  std::uint64_t seed = 1;
  std::string output;
  std::string pcd_encoding = "binary";
};

// The message must name the input; the io layer usually does already.
[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw std::runtime_error(what.find(file) != std::string::npos ? what : file + ": " + what);
}

void run_mesh(const MeshArgs& args) {
  check_output_path(args.output);
  const auto encoding = parse_pcd_encoding(args.pcd_encoding);
  std::optional<Eigen::Vector3d> camera;
  if (!args.view.empty()) camera = parse_point(args.view, "--view");

  io::Mesh mesh;
  try {
    mesh = io::read_mesh(args.file);
  } catch (const std::exception& e) {
    fail(args.file, e.what());
  }

  std::mt19937_64 rng(args.seed);
  PointList points;
  try {
    const auto sample = [&](std::size_t m) {
      return synth::sample_mesh_surface(mesh.vertices, mesh.triangles, m, rng);
    };
    if (camera) {
      // Exact: a point stays when its line of sight crosses no triangle (mesh_visibility.hpp).
      const synth::MeshVisibility visibility(mesh.vertices, mesh.triangles);
      const auto keep = [&](const PointList& candidates) {
        return visibility.visible(candidates, *camera);
      };
      points = synth::sample_visible(sample, keep, args.points, rng);
    } else {
      points = sample(args.points);
    }
  } catch (const std::invalid_argument& e) {
    fail(args.file, e.what());
  }
  synth::add_gaussian_noise(points, args.noise, rng);
  write_cloud(args.output, points, encoding);
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  auto args = std::make_shared<MeshArgs>();
  CLI::App* cmd = app.add_subcommand(
      "mesh", "Area-weighted surface sampling of a mesh (.obj, .ply with faces). No ground truth.");
  cmd->add_option("FILE", args->file, "Mesh file")->required();
  cmd->add_option("--points", args->points, "Points to write")
      ->check(CLI::PositiveNumber)
      ->required();
  cmd->add_option("--view", args->view, "Camera X,Y,Z (mesh units): keep only what it sees");
  cmd->add_option("--noise", args->noise, "Gaussian noise sigma, in the mesh's units")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", args->seed, "Random seed")->capture_default_str();
  cmd->add_option("-o,--output", args->output, "Output cloud (.pcd, .ply, .xyz)")->required();
  cmd->add_option("--pcd-encoding", args->pcd_encoding, "ascii, binary or binary_compressed")
      ->capture_default_str();
  cmd->callback([args] { run_mesh(*args); });
}

}  // namespace cloudshape::synth_tool
