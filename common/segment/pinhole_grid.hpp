// A depth image exported without its grid (PLY, XYZ, a PCD of height 1): its pixels recovered from
// the points' directions, so that it is segmented as the organized frame it was.
#pragma once

#include <optional>

#include "geometry/point_cloud.hpp"

namespace cloudshape::segment {

// The pixel grid of `points` when they are a pinhole camera's depth image in the camera's frame
// (the sensor at the origin looking along +z, as every RGB-D driver writes them, or along -z, as a
// flip for display leaves them) in raster order: every point on the camera's side of its plane, its
// x / z and y / z on two evenly spaced lattices (columns and rows, one step each, either sign, read
// from consecutive points) within a tenth of a step, and the pixels so found strictly increasing.
// Anything else (a scan, a lidar frame, a mesh's samples, points shuffled) gives nothing, mostly
// within the first pass. A few passes over the points, no copy of them.
std::optional<GridLayout> pinhole_grid(const PointList& points);

// Whether there are points and every one lies on one side of the plane z = 0, none on it: a
// camera at the origin looking along +z (or -z) has them all in front of it.
bool beyond_camera_plane(const PointList& points);

}  // namespace cloudshape::segment
