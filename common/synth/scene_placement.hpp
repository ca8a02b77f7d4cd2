// Solids for scenes and the moves that put them flush against planes and each other, exactly:
// every contact comes from the support function, so a touching pair has gap 0 to rounding.
#pragma once

#include <Eigen/Core>
#include <random>

#include "synth/ground_truth.hpp"

namespace cloudshape::synth {

// A solid of `kind` with random tabletop proportions (`unit` = one metre of a table scene),
// in a random stable resting pose on the plane z = 0, centred over the origin.
SolidSpec resting_solid(ShapeKind kind, std::mt19937_64& rng, double unit);

// A box lying on a face with its edges along world x, y, z (any face down), on z = 0.
SolidSpec aligned_box(std::mt19937_64& rng, double unit);

// A cylinder standing on a cap, on z = 0.
SolidSpec standing_cylinder(std::mt19937_64& rng, double unit);

// Smallest and largest value of direction . x over the solid (direction unit).
double lowest(const SolidSpec& spec, const Eigen::Vector3d& direction);
double highest(const SolidSpec& spec, const Eigen::Vector3d& direction);

// Moves the solid along `direction` (unit) until its lowest / highest value along it is `value`.
void set_lowest(SolidSpec& spec, const Eigen::Vector3d& direction, double value);
void set_highest(SolidSpec& spec, const Eigen::Vector3d& direction, double value);

// Turns the solid about the vertical axis through its centre.
void yaw(SolidSpec& spec, double angle);

// Puts `upper` (a box or a solid with a flat bottom) on the top face of the box `lower`, turned
// by a random yaw, its centre above the inner part of that face so it rests stably.
void stack_on(SolidSpec& upper, const SolidSpec& lower, std::mt19937_64& rng);

}  // namespace cloudshape::synth
