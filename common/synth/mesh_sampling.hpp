// Area-weighted sampling of a triangle mesh held in memory (e.g. a YCB scan read by io).
// Independent of any file format so the library stays free of io.
#pragma once

#include "geometry/point_cloud.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace cloudshape::synth {

using Triangle = std::array<std::uint32_t, 3>;

// Throws std::invalid_argument naming the first triangle that refers to a missing vertex.
void check_triangle_indices(const PointList& vertices, const std::vector<Triangle>& triangles);

// Total area of the mesh's triangles. Throws std::invalid_argument on an out-of-range index.
double mesh_area(const PointList& vertices, const std::vector<Triangle>& triangles);

// Exactly n points, uniform by area over the triangles. Degenerate (zero-area or non-finite)
// triangles are skipped. Throws std::invalid_argument on an out-of-range vertex index or when
// the total area is zero.
PointList sample_mesh_surface(const PointList& vertices, const std::vector<Triangle>& triangles,
                              std::size_t n, std::mt19937_64& rng);

}  // namespace cloudshape::synth
