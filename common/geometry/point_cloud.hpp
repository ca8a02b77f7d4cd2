// The point and cloud value types that flow between every stage.
// Plain Eigen vectors in a std::vector: no ownership tricks, no middleware.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

namespace cloudshape {

using Point = Eigen::Vector3d;
using PointList = std::vector<Point>;

// The index of the first point with a coordinate beyond +-max_abs, or points.size() if none.
inline std::size_t first_point_beyond(const PointList& points, double max_abs) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(points[i].cwiseAbs().maxCoeff() <= max_abs)) return i;
  }
  return points.size();
}

}  // namespace cloudshape
