// How far an object's points scatter off their local surface: the noise its resolution must not
// undercut where a depth image's pixels carry noise of their own.
#pragma once

#include <cstddef>

#include "geometry/kdtree.hpp"

namespace cloudshape::pipeline {

// The points' noise off their surface (one deviation): the spread along the least direction (the
// smallest eigenvalue's square root) of the `neighbours` nearest points about up to 2000 evenly
// strided points, the lower quartile of those: a neighbourhood across an edge, a corner or a tight
// bend spreads more than the noise, one on a face by about the noise (the plane through the
// neighbours takes a little of it). 0 for fewer points than `neighbours`. `tree` is over `points`.
double surface_noise(const PointList& points, const geometry::KdTree& tree, std::size_t neighbours);

}  // namespace cloudshape::pipeline
