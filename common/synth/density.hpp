// Uneven sampling density, as real sensors give it: fewer points per area far from the
// camera, and patches (dark or shiny material, glancing angles) where most points are lost.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <random>

#include "geometry/point_cloud.hpp"

namespace cloudshape::synth {

struct DensityVariation {
  // Density falls with the squared distance from this point (a depth camera's pixels spread
  // over d^2 of surface), relative to the nearest point, which keeps full density.
  std::optional<Eigen::Vector3d> falloff_from;
  // 0..1: the share of points lost at the centre of each of kPatches round patches, each of
  // radius 0.2 x the cloud's bounding-box diagonal, the loss fading smoothly to their rim.
  double patchiness = 0.0;
  bool active() const { return falloff_from.has_value() || patchiness > 0.0; }
};

// Keeps each point with the probability the variation gives it (1 with no variation).
// Patch centres are drawn from the points themselves. Throws std::invalid_argument when
// patchiness is outside [0, 1].
PointList thin_by_density(const PointList& points, const DensityVariation& variation,
                          std::mt19937_64& rng);

}  // namespace cloudshape::synth
