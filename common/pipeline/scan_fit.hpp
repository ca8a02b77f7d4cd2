// Whether a solid fitted to a lidar object describes its points: the points' own ranging noise,
// read off their neighbours in the sensor's angles, against how far they scatter about the solid.
#pragma once

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

// The points' ranging noise (one standard deviation) seen from `viewpoint` (the lidar): each
// point's range against the range its two nearest neighbours in direction (on a ring, the returns
// either side of it in azimuth) give at its direction, interpolated between them; the median of
// those differences, each scaled by what the neighbours' own noise adds, as a Gaussian's
// deviation. Neighbours are found by direction because a lidar's angles carry no ranging noise:
// neighbours nearest in space would be those whose noise happens to agree. A surface's own bend
// adds its range's curvature over a ring's angular step, far below the noise at any ring's step.
// 0 when fewer than 3 points have neighbours either side.
double scan_line_noise(const PointList& cloud, const Point& viewpoint);

// How far the points scatter about the solid's surface: the median distance scaled to a
// Gaussian's deviation (robust to the strays a segment keeps at its edges).
double scatter_about(const PointList& cloud, const FittedSolid& solid);

}  // namespace cloudshape::pipeline
