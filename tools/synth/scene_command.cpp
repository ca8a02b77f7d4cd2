// `scene`: objects on a table or floor, touching, stacked or against walls, seen by one depth
// camera or lidar; writes a labelled PCD, its ground truth and the label-to-shape sidecar.
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "arguments.hpp"
#include "cloud_output.hpp"
#include "commands.hpp"
#include "synth/scene_capture.hpp"
#include "synth/scene_truth_json.hpp"

namespace cloudshape::synth_tool {

namespace {

struct SceneArgs {
  std::string layout = "row";
  std::size_t count = 3;
  std::uint64_t seed = 1;
  double scale = 1.0;
  int walls = -1;
  std::size_t width = 640, height = 480;
  std::string fov = "58,45";
  double max_depth = 0.0;
  double depth_noise = 0.0;
  bool quantize = false;
  bool shadows = false;
  double flying_pixels = 0.0;
  std::size_t rings = 32;
  std::string elevation = "-30,10";
  double azimuth_step = 0.2;
  double range_noise = 0.0;
  bool organized = false;
  std::string output;
  std::string pcd_encoding = "binary";
};

std::string sidecar_path(const std::string& cloud_path) {
  return std::filesystem::path(cloud_path).replace_extension(".truth.json").string();
}

void run_scene(const SceneArgs& args) {
  if (std::filesystem::path(args.output).extension() != ".pcd")
    throw std::invalid_argument(args.output +
                                ": a scene is written as .pcd (it carries a label field)");
  const auto encoding = parse_pcd_encoding(args.pcd_encoding);
  const auto layout = synth::scene_layout_from_string(args.layout);
  if (!layout) throw std::invalid_argument("--layout: unknown layout '" + args.layout + "'");
  synth::SceneRecipe recipe;
  recipe.layout = *layout;
  recipe.count = args.count;
  recipe.seed = args.seed;
  recipe.scale = args.scale;
  recipe.walls = args.walls;

  synth::CaptureOptions options;
  options.width = args.width;
  options.height = args.height;
  const auto fov = parse_numbers(args.fov, "--fov");
  if (fov.size() != 2 || !(fov[0] > 0 && fov[0] < 180 && fov[1] > 0 && fov[1] < 180))
    throw std::invalid_argument("--fov: expected H,V degrees in (0, 180), got '" + args.fov + "'");
  options.fov_x_deg = fov[0];
  options.fov_y_deg = fov[1];
  if (args.max_depth > 0.0) options.max_depth = options.max_range = args.max_depth;
  options.depth_noise = args.depth_noise;
  options.quantize = args.quantize;
  options.shadows = args.shadows;
  options.flying_pixels = args.flying_pixels;
  options.rings = args.rings;
  const auto elevation = parse_numbers(args.elevation, "--elevation");
  if (elevation.size() != 2 || !(elevation[0] <= elevation[1]))
    throw std::invalid_argument("--elevation: expected LOW,HIGH degrees, got '" + args.elevation +
                                "'");
  options.min_elevation_deg = elevation[0];
  options.max_elevation_deg = elevation[1];
  options.azimuth_step_deg = args.azimuth_step;
  options.range_noise = args.range_noise;
  options.organized_lidar = args.organized;

  const synth::SceneCapture capture = synth::capture_scene(recipe, options);
  const auto& image = capture.image;
  io::write_labelled_pcd(args.output, image.points, image.labels, image.width, image.height,
                         encoding);
  const std::string source = std::filesystem::path(args.output).filename().string();
  write_json(ground_truth_path(args.output),
             synth::scene_truth_json(source, recipe, capture.generated, capture.scene, image,
                                     capture.sensor));
  write_json(sidecar_path(args.output), synth::scene_groups_json(capture.scene, image));
}

}  // namespace

void add_scene_command(CLI::App& app) {
  auto args = std::make_shared<SceneArgs>();
  CLI::App* cmd = app.add_subcommand(
      "scene",
      "Objects on a table (or floor) among walls, seen by one depth camera (or a lidar); writes "
      "OUT.pcd "
      "(x y z label, organized), OUT.json (truth) and OUT.truth.json (label groups).");
  cmd->add_option("--layout", args->layout, "touching, stacked, row, wall, random or lidar")
      ->capture_default_str();
  cmd->add_option("--count", args->count, "Objects, 1-5 (touching, stacked: 2-5)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed: proportions, poses, camera")
      ->capture_default_str();
  cmd->add_option("--scale", args->scale,
                  "The scene's unit: 1 = metres, 1000 = the same scene in mm")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--walls", args->walls, "0, 1 or 2 walls (default: wall 1, lidar 2, others 0)")
      ->check(CLI::Range(0, 2));
  cmd->add_option("--width", args->width, "Camera image width (pixels)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--height", args->height, "Camera image height (pixels)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--fov", args->fov, "Camera field of view H,V (degrees)")->capture_default_str();
  cmd->add_option(
         "--max-depth", args->max_depth,
         "Nothing seen beyond this depth (camera) or range (lidar), in metres x scale; 0: no limit")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option(
         "--depth-noise", args->depth_noise,
         "Depth noise sigma = K z^2, sigma and z in metres (times --scale); Kinect about 0.0019")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--quantize", args->quantize,
                "Kinect disparity quantisation (1/8 px, 7.5 cm baseline)");
  cmd->add_flag("--shadows", args->shadows,
                "Kinect projector shadows (projector 7.5 cm beside the camera)");
  cmd->add_option("--flying-pixels", args->flying_pixels,
                  "0..1: share of the pixels at depth jumps given a depth between the two surfaces "
                  "(they keep their label)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--rings", args->rings, "Lidar beams")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--elevation", args->elevation, "Lidar beam elevations LOW,HIGH (degrees)")
      ->capture_default_str();
  cmd->add_option("--azimuth-step", args->azimuth_step, "Lidar azimuth step (degrees)")
      ->check(CLI::Range(0.01, 90.0))
      ->capture_default_str();
  cmd->add_option("--range-noise", args->range_noise, "Lidar range sigma, metres x scale")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--organized", args->organized,
                "Lidar: write the rings x azimuth grid, NaN for no return");
  cmd->add_option("-o,--output", args->output, "Output cloud (.pcd)")->required();
  cmd->add_option("--pcd-encoding", args->pcd_encoding, "ascii, binary or binary_compressed")
      ->capture_default_str();
  cmd->callback([args] { run_scene(*args); });
}

}  // namespace cloudshape::synth_tool
