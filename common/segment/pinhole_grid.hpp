// A depth image exported without its grid (PLY, XYZ, a PCD of height 1): its pixels recovered from
// the points' directions, so that it is segmented as the organized frame it was.
#pragma once

#include <optional>

#include "geometry/point_cloud.hpp"

namespace cloudshape::segment {

// The pixel grid of `points` when they are a pinhole camera's depth image in the camera's frame
// (the sensor at the origin looking along +z, as every RGB-D driver writes them) in raster order:
// every point in front of the camera (z > 0), its x / z and y / z on two evenly spaced lattices
// (columns and rows, one step each, read from consecutive points) within a tenth of a step, and
// the pixels so found strictly increasing. Anything else (a scan, a lidar frame, a mesh's samples,
// points shuffled) gives nothing, mostly after a few hundred points. One pass over the points.
std::optional<GridLayout> pinhole_grid(const PointList& points);

}  // namespace cloudshape::segment
