// The oriented bounding box of a point set: the tightest (by volume) of a few candidate
// frames, each bounding every point exactly. For an object's `extent` (INTERFACE.md).
#pragma once

#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::parallel {
class ThreadPool;
}  // namespace cloudshape::parallel

namespace cloudshape::geometry {

struct OrientedBox {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  // Rows: unit directions, right-handed, sorted so that size[0] >= size[1] >= size[2].
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  // full edge lengths along axes[0..2]
};

// Starts from the principal axes and from each row-frame of `hints` (e.g. a fitted solid's
// axes); from each, rounds turn the frame about each of its axes to the minimum-area rectangle
// of the points projected across it (rotating calipers on a convex hull) while the volume
// falls. The frame is chosen on at most `hull_samples` points; the bounds take every point,
// so every point lies inside. An empty set gives a zero box at the origin. A `pool` works from
// the starts side by side: the same box.
OrientedBox oriented_bounding_box(const PointList& points,
                                  const std::vector<Eigen::Matrix3d>& hints = {},
                                  std::size_t hull_samples = 2000,
                                  parallel::ThreadPool* pool = nullptr);

namespace detail {
// The unit direction of the first side of the minimum-area rectangle round `hull` (a convex
// polygon, counter-clockwise): the first of its edges whose rectangle round every vertex has the
// least area (UnitX if none has a finite one).
Eigen::Vector2d min_area_direction(const std::vector<Eigen::Vector2d>& hull);
}  // namespace detail

}  // namespace cloudshape::geometry
