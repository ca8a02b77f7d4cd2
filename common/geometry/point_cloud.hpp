// The point and cloud value types that flow between every stage.
// Plain Eigen vectors in a std::vector: no ownership tricks, no middleware.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cloudshape {

using Point = Eigen::Vector3d;
using PointList = std::vector<Point>;

// Where each point sat in the sensor's image, for an organized cloud (a depth camera's
// width x height grid, invalid pixels absent); empty for an unorganized cloud.
struct GridLayout {
  std::size_t width = 0;
  std::size_t height = 0;
  std::vector<std::uint32_t> pixel;  // per point: row * width + column, increasing

  bool organized() const { return height > 1 && width > 0 && !pixel.empty(); }
};

// The index of the first point with a coordinate beyond +-max_abs, or points.size() if none.
inline std::size_t first_point_beyond(const PointList& points, double max_abs) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(points[i].cwiseAbs().maxCoeff() <= max_abs)) return i;
  }
  return points.size();
}

}  // namespace cloudshape
