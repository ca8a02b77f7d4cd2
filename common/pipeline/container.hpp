// A round surface seen from its hollow side (a bowl seen over its rim) is the inside of a
// container, never a sphere seen from outside: the container's envelope cylinder replaces it.
#pragma once

#include <optional>

#include "config/stage_configs.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

// True when most points of `sphere`'s surface face away from `viewpoint`: the sensor looks at
// its inside. cfg.inside_view_share is that share.
bool seen_from_inside(const PointList& cloud, const FittedSolid& sphere, const Point& viewpoint,
                      const config::SolveConfig& cfg);

// The container whose hollow is `sphere`'s cap: the cylinder about the axis from the sphere's
// centre through the points' centroid, as wide as the rim (cfg.container_rim_quantile of the
// points' distances from the axis) and as deep as the points reach along the axis. Its points
// are explained by the hollow or the wall (its signed distance is the nearer of the two inside).
std::optional<FittedSolid> container_of_hollow(const PointList& cloud, const FittedSolid& sphere,
                                               const config::SolveConfig& cfg);

}  // namespace cloudshape::pipeline
