// Ray casting of the depth camera and the lidar. Noise and quantisation move a point along its
// own ray, so pixel i stays on the ray of pixel i.
#include "synth/range_sensor.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace cloudshape::synth {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

Eigen::Vector3d nan_point() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {nan, nan, nan};
}

// True when something lies between the projector and the surface point p.
bool in_shadow(const SceneRayCaster& caster, const Eigen::Vector3d& projector,
               const Eigen::Vector3d& p) {
  const Eigen::Vector3d to_point = p - projector;
  const double distance = to_point.norm();
  const SceneHit hit = caster.cast(projector, to_point / distance, distance);
  // The light's own hit on p's surface comes back at `distance` to rounding.
  return hit.label != 0 && hit.t < distance * (1.0 - 1e-9);
}

// Depth edges blur as a Kinect's do: a pixel beside a jump of more than 5% of its depth takes,
// with probability `share`, a depth drawn between its own and its neighbour's across the jump.
std::vector<double> with_flying_pixels(const std::vector<double>& depth, std::size_t w,
                                       std::size_t h, double share, std::mt19937_64& rng) {
  std::vector<double> out = depth;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < w * h; ++i) {
    if (!std::isfinite(depth[i])) continue;
    const std::size_t row = i / w, column = i % w;
    double across = depth[i];
    const auto consider = [&](std::size_t j) {
      if (std::isfinite(depth[j]) && std::abs(depth[j] - depth[i]) > 0.05 * depth[i] &&
          std::abs(depth[j] - depth[i]) > std::abs(across - depth[i]))
        across = depth[j];
    };
    if (column > 0) consider(i - 1);
    if (column + 1 < w) consider(i + 1);
    if (row > 0) consider(i - w);
    if (row + 1 < h) consider(i + w);
    if (across != depth[i] && u(rng) < share) out[i] = depth[i] + u(rng) * (across - depth[i]);
  }
  return out;
}

}  // namespace

SensorPose look_at(const Eigen::Vector3d& position, const Eigen::Vector3d& target,
                   const Eigen::Vector3d& up) {
  const Eigen::Vector3d z = (target - position).normalized();
  const Eigen::Vector3d x = z.cross(up).normalized();
  SensorPose pose;
  pose.position = position;
  pose.axes.row(0) = x.transpose();
  pose.axes.row(1) = z.cross(x).transpose();
  pose.axes.row(2) = z.transpose();
  return pose;
}

double DepthCamera::focal_x() const { return 0.5 * width / std::tan(0.5 * fov_x_deg * kDeg); }

Eigen::Vector3d DepthCamera::pixel_ray(std::size_t column, std::size_t row) const {
  const double fy = 0.5 * height / std::tan(0.5 * fov_y_deg * kDeg);
  return {(column + 0.5 - 0.5 * width) / focal_x(), (row + 0.5 - 0.5 * height) / fy, 1.0};
}

std::size_t Lidar::columns() const {
  return static_cast<std::size_t>(std::llround(360.0 / azimuth_step_deg));
}

Eigen::Vector3d Lidar::beam(std::size_t ring, std::size_t column) const {
  const double elevation = rings < 2 ? min_elevation_deg
                                     : min_elevation_deg + (max_elevation_deg - min_elevation_deg) *
                                                               ring / (rings - 1.0);
  const double azimuth = column * azimuth_step_deg * kDeg;
  const double e = elevation * kDeg;
  return {std::cos(e) * std::cos(azimuth), std::cos(e) * std::sin(azimuth), std::sin(e)};
}

RangeImage render(const Scene& scene, const DepthCamera& camera, const SensorPose& pose,
                  std::mt19937_64& rng) {
  const Scene local = transformed(scene, pose.axes, pose.position);
  const SceneRayCaster caster(local);
  const std::size_t w = camera.width, h = camera.height;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> depth(w * h, nan);
  RangeImage image{w, h, {}, std::vector<std::uint32_t>(w * h, 0)};
  const Eigen::Vector3d projector(camera.projector_offset, 0.0, 0.0);
  for (std::size_t row = 0; row < h; ++row) {
    for (std::size_t column = 0; column < w; ++column) {
      const Eigen::Vector3d ray = camera.pixel_ray(column, row);
      const double length = ray.norm();
      // Range along the unit ray up to the depth limit (depth = range / length since ray.z = 1).
      const SceneHit hit =
          caster.cast(Eigen::Vector3d::Zero(), ray / length, camera.max_depth * length);
      if (hit.label == 0) continue;
      if (camera.projector_offset > 0.0 && in_shadow(caster, projector, hit.t * ray / length))
        continue;
      depth[row * w + column] = hit.t / length;
      image.labels[row * w + column] = hit.label;
    }
  }
  if (camera.flying_pixels > 0.0)
    depth = with_flying_pixels(depth, w, h, camera.flying_pixels, rng);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double focal_baseline = camera.focal_x() * camera.baseline;
  image.points.reserve(w * h);
  for (std::size_t i = 0; i < w * h; ++i) {
    double z = depth[i];
    if (!std::isfinite(z)) {
      image.points.push_back(nan_point());
      continue;
    }
    if (camera.noise_k > 0.0) z += camera.noise_k * z * z * gauss(rng);
    if (focal_baseline > 0.0) {
      const double steps = std::max(1.0, std::round(focal_baseline / z / camera.disparity_step));
      z = focal_baseline / (steps * camera.disparity_step);
    }
    image.points.push_back(z * camera.pixel_ray(i % w, i / w));
  }
  return image;
}

RangeImage render(const Scene& scene, const Lidar& lidar, const SensorPose& pose,
                  std::mt19937_64& rng) {
  const Scene local = transformed(scene, pose.axes, pose.position);
  const SceneRayCaster caster(local);
  const std::size_t columns = lidar.columns();
  RangeImage image{columns, lidar.rings, {}, {}};
  image.points.reserve(columns * lidar.rings);
  image.labels.reserve(columns * lidar.rings);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (std::size_t ring = 0; ring < lidar.rings; ++ring) {
    for (std::size_t column = 0; column < columns; ++column) {
      const Eigen::Vector3d beam = lidar.beam(ring, column);
      const SceneHit hit = caster.cast(Eigen::Vector3d::Zero(), beam, lidar.max_range);
      if (hit.label == 0) {
        image.points.push_back(nan_point());
        image.labels.push_back(0);
        continue;
      }
      const double range = hit.t + (lidar.range_noise > 0.0 ? lidar.range_noise * gauss(rng) : 0.0);
      image.points.push_back(range * beam);
      image.labels.push_back(hit.label);
    }
  }
  return image;
}

}  // namespace cloudshape::synth
