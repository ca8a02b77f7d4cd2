// A flat square seen square on or turned by a depth camera, each pixel's depth off along its ray:
// a far face whose noise exceeds the pixels' spacing, for the stages that read a view's noise.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "geometry/point_cloud.hpp"

namespace cloudshape::testing {

// A 12 x 12 cm square 1.8 m before a depth camera (525-pixel focal length: 3.4 mm between pixels
// there), turned `tilt` radians about the x axis, each pixel's depth off by `noise` along its ray.
inline PointList noisy_view(double noise, double tilt, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double depth = 1.8, focal = 525.0;
  const Eigen::Vector3d normal(0.0, -std::sin(tilt), std::cos(tilt));
  const Eigen::Vector3d centre(0.0, 0.0, depth);
  PointList points;
  for (int row = -60; row <= 60; ++row) {
    for (int col = -60; col <= 60; ++col) {
      const Eigen::Vector3d ray = Eigen::Vector3d(col / focal, row / focal, 1.0).normalized();
      const double range = normal.dot(centre) / normal.dot(ray);
      const Eigen::Vector3d in_plane = range * ray - centre;
      if (std::abs(in_plane.x()) > 0.06 || std::abs(in_plane.y()) > 0.06 * std::cos(tilt) + 1e-9)
        continue;
      points.push_back((range + noise * gauss(rng)) * ray);
    }
  }
  return points;
}

}  // namespace cloudshape::testing
