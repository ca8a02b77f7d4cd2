// A box's surface sampled at random for the tests: each point on a face picked by area, the box
// `size` from its corner at the origin, turned by `turn` and moved by `offset`.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <random>

#include "geometry/point_cloud.hpp"

namespace cloudshape::testing {

inline PointList box_surface(const Eigen::Vector3d& size, const Eigen::Matrix3d& turn, const Eigen::Vector3d& offset,
                             std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double areas[3] = {size.y() * size.z(), size.x() * size.z(), size.x() * size.y()};
  PointList pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double pick = u(rng) * (areas[0] + areas[1] + areas[2]);
    const int axis = pick < areas[0] ? 0 : pick < areas[0] + areas[1] ? 1 : 2;
    Eigen::Vector3d p(u(rng) * size.x(), u(rng) * size.y(), u(rng) * size.z());
    p[axis] = u(rng) < 0.5 ? 0.0 : size[axis];
    pts.push_back(turn * p + offset);
  }
  return pts;
}

}  // namespace cloudshape::testing
