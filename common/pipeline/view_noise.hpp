// How far a view's points scatter off their surface, with neighbours chosen by their direction
// from the sensor: a depth sensor's noise runs along its rays, and nearest points in space do not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "geometry/point_cloud.hpp"

namespace cloudshape::pipeline {

// The points' noise off their surface (one deviation) seen from `viewpoint`: about up to 256
// evenly strided points (a median's worth: the search tree over every point's direction costs the
// most), the `neighbours` points nearest in direction from the viewpoint (a depth image's
// neighbouring pixels, whatever their depth), their depth along the ray regressed on their place
// across it, and their deviation off that plane (n - 3 degrees of freedom); the median of those.
// Where the noise exceeds the points' spacing, the points nearest in space are those whose noise
// agrees, and read a third to a half of it. 0 for fewer points than `neighbours`.
double noise_along_view(const PointList& points, const Point& viewpoint, std::size_t neighbours);

// The rays whose points read a depth image's noise about one of them: its 4 x 4 pixels, as many
// as surface_noise's neighbourhoods.
constexpr std::size_t kViewNoiseRays = 16;

// The viewpoint whose rays read the noise: a depth camera's, not a lidar's (`scan_lines` > 0),
// whose nearest rays run along one ring, where no plane across them is determined.
inline std::optional<Point> noise_viewpoint(const std::optional<Point>& viewpoint,
                                            std::uint32_t scan_lines) {
  return scan_lines == 0 ? viewpoint : std::nullopt;
}

}  // namespace cloudshape::pipeline
