// Objects of each shape at a known pose, as the solver reports them, for the common/ros2 tests.
// Their axes are a fixed rotation away from the frame's, so no test passes by an identity.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <utility>
#include <vector>

#include "pipeline/result.hpp"

namespace cloudshape::ros2::test {

inline Eigen::Matrix3d test_rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

inline pipeline::ObjectResult object(const std::string& shape,
                                     std::vector<std::pair<std::string, double>> dimensions) {
  pipeline::ObjectResult o;
  o.shape = shape;
  o.confidence = 0.875;
  o.dimensions = std::move(dimensions);
  o.center = Eigen::Vector3d(1.5, -2.0, 4.25);
  o.axes = test_rotation().transpose();  // rows are the axes
  return o;
}

}  // namespace cloudshape::ros2::test
