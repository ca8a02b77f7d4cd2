// The cameras a picture is seen from: the sensor's own (at the origin, looking along +z), one
// along a cloud's principal axes when no sensor pose is known, and an oblique one around a pivot.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "render/view.hpp"

namespace cloudshape::render {

// The depth camera's frame of an organized cloud: x right, y down, z forward, pinhole.
Camera sensor_camera();

// Orthographic, looking along the cloud's direction of least spread from the side where
// `viewer_side` is (where a sensor most likely was), its direction of greatest spread to the right.
Camera principal_axes_camera(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& viewer_side);

// Orthographic, `base` turned about `pivot` by `azimuth_deg` to the right and `elevation_deg`
// upwards (in base's own right and down directions), still looking at `pivot`.
Camera oblique_camera(const Camera& base, const Eigen::Vector3d& pivot, double azimuth_deg,
                      double elevation_deg);

}  // namespace cloudshape::render
