// Poses of solids lying at rest on a horizontal table (world z up), as a camera above a table
// sees them: on a face, a cap, or a cone's or cylinder's side.
#pragma once

#include <random>

#include "synth/ground_truth.hpp"

namespace cloudshape::synth {

// Turns `spec` so that one of its resting faces lies flat on a plane normal to world z, below
// the solid, then by a random angle about z; the centre is kept. The face is chosen uniformly
// among the solid's kinds of rest: box, tetrahedron: any face; pentagonal prism: a cap or a
// side face (even odds); cylinder: a cap or the side; cone: the base or the side (lying on a
// generator line); sphere: any orientation.
void place_at_rest(SolidSpec& spec, std::mt19937_64& rng);

}  // namespace cloudshape::synth
