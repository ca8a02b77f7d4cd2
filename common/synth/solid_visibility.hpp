// Exact single-view visibility for clouds sampled from the analytic solids: back faces culled
// by the surface normal, points hidden behind another solid removed by a segment test.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/point_cloud.hpp"
#include "synth/ground_truth.hpp"

namespace cloudshape::synth {

// Keeps the points (each on the surface of one of `solids`, which are disjoint and convex)
// that a pinhole camera at `camera` sees: the surface under the point faces the camera (a
// surface seen exactly edge-on counts as hidden) and the line of sight enters no other solid.
// Nothing of a back face leaks past a silhouette (a point z-buffer would let slivers through).
PointList visible_on_solids(const PointList& points, const std::vector<SolidSpec>& solids,
                            const Eigen::Vector3d& camera);

}  // namespace cloudshape::synth
