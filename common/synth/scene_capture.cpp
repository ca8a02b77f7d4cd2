// Scales the capture options by the scene unit, renders with the right sensor and drops the
// empty returns of an unorganized lidar frame.
#include "synth/scene_capture.hpp"

#include <cmath>

namespace cloudshape::synth {

namespace {

RangeImage returns_only(const RangeImage& image) {
  RangeImage out;
  for (std::size_t i = 0; i < image.points.size(); ++i) {
    if (image.labels[i] == 0) continue;
    out.points.push_back(image.points[i]);
    out.labels.push_back(image.labels[i]);
  }
  out.width = out.points.size();
  out.height = 1;
  return out;
}

}  // namespace

SceneCapture capture_scene(const SceneRecipe& recipe, const CaptureOptions& options) {
  SceneRecipe scaled = recipe;
  scaled.fov_y_deg = options.fov_y_deg;
  SceneCapture capture;
  capture.generated = make_scene(scaled);
  const double unit = recipe.scale;
  // Noise draws come from their own stream so they never change the scene.
  std::seed_seq noise_seed{recipe.seed, std::uint64_t{0x6e6f697365}};
  std::mt19937_64 rng(noise_seed);
  const SensorPose& pose = capture.generated.sensor;
  capture.scene = transformed(capture.generated.scene, pose.axes, pose.position);
  if (capture.generated.lidar) {
    Lidar lidar;
    lidar.rings = options.rings;
    lidar.min_elevation_deg = options.min_elevation_deg;
    lidar.max_elevation_deg = options.max_elevation_deg;
    lidar.azimuth_step_deg = options.azimuth_step_deg;
    lidar.max_range = options.max_range * unit;
    lidar.range_noise = options.range_noise * unit;
    capture.image = render(capture.generated.scene, lidar, pose, rng);
    if (!options.organized_lidar) capture.image = returns_only(capture.image);
    capture.sensor = {
        {"type", "lidar"},
        {"rings", lidar.rings},
        {"elevation_deg", {lidar.min_elevation_deg, lidar.max_elevation_deg}},
        {"azimuth_step_deg", lidar.azimuth_step_deg},
        {"range_noise", lidar.range_noise},
        {"organized", options.organized_lidar},
        {"position_world", {pose.position.x(), pose.position.y(), pose.position.z()}}};
  } else {
    DepthCamera camera;
    camera.width = options.width;
    camera.height = options.height;
    camera.fov_x_deg = options.fov_x_deg;
    camera.fov_y_deg = options.fov_y_deg;
    camera.max_depth = options.max_depth * unit;
    camera.noise_k = options.depth_noise / unit;
    camera.baseline = options.quantize ? 0.075 * unit : 0.0;
    camera.projector_offset = options.shadows ? 0.075 * unit : 0.0;
    camera.flying_pixels = options.flying_pixels;
    capture.image = render(capture.generated.scene, camera, pose, rng);
    capture.sensor = {
        {"type", "depth_camera"},
        {"width", camera.width},
        {"height", camera.height},
        {"fov_deg", {camera.fov_x_deg, camera.fov_y_deg}},
        {"focal_px", camera.focal_x()},
        {"depth_noise_k", camera.noise_k},
        {"baseline", camera.baseline},
        {"projector_offset", camera.projector_offset},
        {"position_world", {pose.position.x(), pose.position.y(), pose.position.z()}}};
  }
  return capture;
}

}  // namespace cloudshape::synth
