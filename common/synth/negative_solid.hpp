// Solids outside cloudshape's vocabulary (ellipsoid, torus, square pyramid, octahedron, capsule) as
// posed triangle meshes: the negatives an honest recognizer must call `unknown`.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "synth/mesh_solids.hpp"

namespace cloudshape::synth {

enum class NegativeKind { ellipsoid, torus, square_pyramid, octahedron, capsule };

const std::vector<NegativeKind>& all_negative_kinds();
std::string to_string(NegativeKind kind);

// A random solid of the kind, largest extent `size`, uniformly rotated, centre within +-size of
// the origin. Proportions stay well away from the vocabulary's shapes: the ellipsoid's three
// semi-axes differ by at least 25% each, the pyramid is no tetrahedron, the octahedron's
// faces are no box's, the capsule's domes (radius 20-30% of its length) are no cylinder's caps.
SolidMesh random_negative_solid(NegativeKind kind, std::mt19937_64& rng, double size);

}  // namespace cloudshape::synth
