// The point and cloud value types that flow between every stage.
// Plain Eigen vectors in a std::vector: no ownership tricks, no middleware.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace cloudshape {

using Point = Eigen::Vector3d;
using PointList = std::vector<Point>;

}  // namespace cloudshape
