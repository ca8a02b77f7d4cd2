// The structure of a table scene (a support plane wider than its objects, walls meeting it at
// its edges) and the camera that looks at it from above and in front of the walls.
#include <algorithm>
#include <cmath>

#include "synth/scene_layout.hpp"
#include "synth/scene_placement.hpp"

namespace cloudshape::synth {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX(), kY = Eigen::Vector3d::UnitY(),
                      kZ = Eigen::Vector3d::UnitZ();

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

struct Footprint {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, top = 0.0;
};

Footprint footprint(const Scene& scene) {
  Footprint f;
  for (const auto& o : scene.objects) {
    f.x0 = std::min(f.x0, lowest(o.solid, kX)), f.x1 = std::max(f.x1, highest(o.solid, kX));
    f.y0 = std::min(f.y0, lowest(o.solid, kY)), f.y1 = std::max(f.y1, highest(o.solid, kY));
    f.top = std::max(f.top, highest(o.solid, kZ));
  }
  return f;
}

}  // namespace

void add_structure(Scene& scene, std::optional<double> back_wall_y,
                   std::optional<double> side_wall_x, double unit, std::mt19937_64& rng) {
  const Footprint f = footprint(scene);
  const double mx = (f.x1 - f.x0) * uniform(rng, 0.3, 0.6) + 0.1 * unit;
  const double my = (f.y1 - f.y0) * uniform(rng, 0.3, 0.6) + 0.1 * unit;
  const double x0 = f.x0 - mx, y0 = f.y0 - my;
  // A table against a wall ends at the wall.
  const double x1 = side_wall_x.value_or(f.x1 + mx), y1 = back_wall_y.value_or(f.y1 + my);
  scene.structure.push_back({"plane", Eigen::Vector3d(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.0), kX,
                             kY, 0.5 * (x1 - x0), 0.5 * (y1 - y0), 1});
  const double wall_half = 0.4 * std::max(x1 - x0, y1 - y0) + 0.5 * f.top;
  if (back_wall_y)
    scene.structure.push_back({"wall", Eigen::Vector3d(0.5 * (x0 + x1), *back_wall_y, wall_half),
                               kX, kZ, 0.5 * (x1 - x0), wall_half, 2});
  if (side_wall_x)
    scene.structure.push_back({"wall", Eigen::Vector3d(*side_wall_x, 0.5 * (y0 + y1), wall_half),
                               kY, kZ, 0.5 * (y1 - y0), wall_half, back_wall_y ? 3u : 2u});
}

SensorPose table_camera(const Scene& scene, int walls, bool along_row, double fov_y_deg,
                        std::mt19937_64& rng) {
  const Footprint f = footprint(scene);
  const Eigen::Vector3d target(0.5 * (f.x0 + f.x1), 0.5 * (f.y0 + f.y1), 0.3 * f.top);
  // The objects fill about three quarters of the image height.
  const double radius = 0.5 * std::hypot(f.x1 - f.x0, f.y1 - f.y0) + 0.5 * f.top;
  const double distance = radius / std::tan(0.5 * 0.75 * fov_y_deg * kDeg);
  // Lower along a row, where the objects are to hide each other.
  const double elevation = (along_row ? uniform(rng, 20.0, 35.0) : uniform(rng, 35.0, 60.0)) * kDeg;
  // From the front (-y), from the -x side when a side wall stands at +x, and 10-30 degrees off
  // the row's line (the x axis) to look along a row.
  double azimuth_deg = walls >= 2 ? uniform(rng, -125.0, -100.0) : uniform(rng, -120.0, -60.0);
  if (along_row) {
    const double off_line = uniform(rng, 10.0, 30.0);
    azimuth_deg = walls >= 2 || uniform(rng, 0.0, 1.0) < 0.5 ? -180.0 + off_line : -off_line;
  }
  const double azimuth = azimuth_deg * kDeg;
  const Eigen::Vector3d position =
      target + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                          std::cos(elevation) * std::sin(azimuth),
                                          std::sin(elevation));
  return look_at(position, target);
}

}  // namespace cloudshape::synth
