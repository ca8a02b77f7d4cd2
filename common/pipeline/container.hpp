// A round surface seen from its hollow side (a bowl seen over its rim) is the inside of a
// container, never a convex solid seen from outside: the container's envelope cylinder replaces it.
#pragma once

#include <optional>

#include "config/stage_configs.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

// True for a sphere, cone or frustum most of whose points (cfg.inside_view_share) have the
// solid's outward normal (its signed distance's gradient, by differences over `step`) facing
// away from `viewpoint`: the sensor looks at its inside.
bool seen_from_inside(const PointList& cloud, const FittedSolid& solid, const Point& viewpoint, double step,
                      const config::SolveConfig& cfg);

// The container whose hollow is `hollow`'s surface: the cylinder about the hollow's axis (a
// sphere's: the points' thinnest direction), as wide as the rim
// (cfg.container_rim_quantile of the points' distances from the axis) and as deep as the points
// reach along it. Points are explained by the hollow or the wall (inside, the nearer of the two).
std::optional<FittedSolid> container_of_hollow(const PointList& cloud, const FittedSolid& hollow,
                                               const config::SolveConfig& cfg);

}  // namespace cloudshape::pipeline
