// Drawing exactly n points that a single-view visibility filter keeps, with uniform density.
// The filters themselves are exact: solid_visibility.hpp (analytic solids), mesh_visibility.hpp.
#pragma once

#include "geometry/point_cloud.hpp"

#include <cstddef>
#include <functional>
#include <random>

namespace cloudshape::synth {

// Draws from `sample(m)` (m area-uniform surface points) and keeps what `keep_visible` keeps
// (points in, the visible ones out), oversampling so the result has exactly n points where
// possible (fewer only when almost nothing is visible). Keeps the visible density uniform: the
// surplus is removed by uniform random subsampling.
PointList sample_visible(const std::function<PointList(std::size_t)>& sample,
                         const std::function<PointList(const PointList&)>& keep_visible,
                         std::size_t n, std::mt19937_64& rng);

}  // namespace cloudshape::synth
