// The two sensors of synthetic scenes: a pinhole depth camera (Kinect-like, organized image)
// and a spinning lidar (rings of beams), each ray-cast exactly against a Scene.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "synth/scene.hpp"

namespace cloudshape::synth {

// A sensor's pose: its position and its axes (rows, in world coordinates). A camera looks along
// its +z with x right and y down in the image; a lidar's z is its spin axis.
struct SensorPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
};

// A camera at `position` looking at `target`, the image's up towards world `up`.
SensorPose look_at(const Eigen::Vector3d& position, const Eigen::Vector3d& target,
                   const Eigen::Vector3d& up = Eigen::Vector3d::UnitZ());

struct DepthCamera {
  std::size_t width = 640, height = 480;
  double fov_x_deg = 58.0, fov_y_deg = 45.0;
  double max_depth = std::numeric_limits<double>::infinity();  // farther pixels are empty
  // Depth noise sigma = noise_k * z^2 (z the depth), Kinect-like; 0 for none.
  double noise_k = 0.0;
  // Kinect-like disparity quantisation: z = focal * baseline / d with d in steps of
  // disparity_step pixels. 0 baseline for none.
  double baseline = 0.0;
  double disparity_step = 0.125;
  // A structured-light camera sees only what its projector lights: with a projector this far
  // along the camera's +x, pixels in the projector's shadow are empty. 0 for none.
  double projector_offset = 0.0;
  // Share of the pixels beside a depth jump that fly: their depth falls between the two
  // surfaces (they keep their pixel's label but lie on no surface). 0 for none.
  double flying_pixels = 0.0;

  // Direction of pixel (column, row) in the camera frame, with z = 1.
  Eigen::Vector3d pixel_ray(std::size_t column, std::size_t row) const;
  double focal_x() const;
};

// Rings of beams at evenly spaced elevations, swept in azimuth over a full turn.
struct Lidar {
  std::size_t rings = 32;
  double min_elevation_deg = -30.0, max_elevation_deg = 10.0;
  double azimuth_step_deg = 0.2;
  double max_range = std::numeric_limits<double>::infinity();
  double range_noise = 0.0;  // sigma, absolute, along the beam

  std::size_t columns() const;
  // Unit beam direction in the lidar's frame (x forward at azimuth 0, z up).
  Eigen::Vector3d beam(std::size_t ring, std::size_t column) const;
};

// One frame in the sensor's own coordinates: width * height points, row-major (row = image row
// or lidar ring), NaN where nothing was hit; labels 0 there, the surface's label elsewhere.
struct RangeImage {
  std::size_t width = 0, height = 0;
  PointList points;
  std::vector<std::uint32_t> labels;
};

RangeImage render(const Scene& scene, const DepthCamera& camera, const SensorPose& pose,
                  std::mt19937_64& rng);
RangeImage render(const Scene& scene, const Lidar& lidar, const SensorPose& pose,
                  std::mt19937_64& rng);

}  // namespace cloudshape::synth
