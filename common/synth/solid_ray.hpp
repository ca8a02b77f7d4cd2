// Where a ray first meets one of the analytic solids, exactly (to rounding), for ray-cast
// depth images: the same surface the samplers and the test oracle describe.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "synth/ground_truth.hpp"

namespace cloudshape::synth {

// The smallest t in [t_near, t_far] at which origin + t * direction (direction unit) is on the
// surface of `spec`, for a ray that enters the solid's inside; nullopt for a miss or a ray that
// only grazes it. `radius` bounds the solid about pose.center (bounding_radius).
std::optional<double> first_hit(const SolidSpec& spec, double radius, const Eigen::Vector3d& origin,
                                const Eigen::Vector3d& direction, double t_near, double t_far);

}  // namespace cloudshape::synth
