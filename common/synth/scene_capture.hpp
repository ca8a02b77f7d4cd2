// One call from a scene recipe to a sensor frame with exact truth: the scene, the sensor that
// sees it (a depth camera, or a lidar for the lidar layout) and the labelled range image.
#pragma once

#include <limits>
#include <nlohmann/json.hpp>

#include "synth/range_sensor.hpp"
#include "synth/scene_layout.hpp"

namespace cloudshape::synth {

// Lengths here are in the scene's reference unit (a metre at scale 1) and multiplied by the
// recipe's scale, so one set of options fits a table in metres and one in millimetres.
struct CaptureOptions {
  std::size_t width = 640, height = 480;
  double fov_x_deg = 58.0, fov_y_deg = 45.0;
  double max_depth = std::numeric_limits<double>::infinity();
  double depth_noise = 0.0;  // sigma = depth_noise * z^2 with z in reference units (Kinect ~0.0019)
  bool quantize = false;     // Kinect disparity steps: baseline 0.075, 1/8 pixel
  bool shadows = false;      // Kinect projector shadows: the projector 0.075 beside the camera
  double flying_pixels = 0.0;  // share of the pixels at depth jumps given a depth in between
  std::size_t rings = 32;
  double min_elevation_deg = -30.0, max_elevation_deg = 10.0, azimuth_step_deg = 0.2;
  double max_range = std::numeric_limits<double>::infinity();
  double range_noise = 0.0;      // lidar range sigma
  bool organized_lidar = false;  // rings x azimuth grid; otherwise only the returns, unorganized
};

struct SceneCapture {
  GeneratedScene generated;  // world frame
  Scene scene;               // in the sensor's frame, the frame of `image`
  RangeImage image;          // unorganized lidar: height 1, returns only
  nlohmann::json sensor;     // what the truth file records about the sensor
};

SceneCapture capture_scene(const SceneRecipe& recipe, const CaptureOptions& options);

}  // namespace cloudshape::synth
