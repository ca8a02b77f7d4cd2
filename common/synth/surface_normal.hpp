// Outward surface normals of the analytic solids, for exact visibility of single views.
// Each solid is a convex region, the maximum of a few constraints; the active one gives the normal.
#pragma once

#include <Eigen/Core>

#include "synth/ground_truth.hpp"

namespace cloudshape::synth {

struct SurfaceContact {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // outward unit normal, world frame
  double residual = 0.0;  // the active constraint: ~0 on the surface, < 0 inside, > 0 outside
};

// The surface constraint of `spec` that is active at the world point (the largest one).
SurfaceContact surface_contact(const SolidSpec& spec, const Eigen::Vector3d& world);

// True when the segment from `from` to `to` passes through the inside of the solid (its
// constraint drops below -margin somewhere on the segment). The constraint is convex along
// any line, so a golden-section search finds its minimum.
bool segment_enters(const SolidSpec& spec, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                    double margin);

}  // namespace cloudshape::synth
