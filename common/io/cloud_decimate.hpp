// An organized cloud at a lower resolution: every N-th pixel of every N-th row, on a grid N times
// smaller each way, as a depth camera run at that resolution gives its frame.
#pragma once

#include <cstddef>

#include "io/cloud_file.hpp"

namespace cloudshape::io {

// The points of `cloud` on pixels whose row and column are multiples of `step`, in their order,
// each with its label (when the cloud has labels) and its pixel on the grid of ceil(width / step)
// x ceil(height / step). `cloud` must be organized (grid.organized()); `step` >= 1 (1: a copy).
CloudFile decimated(const CloudFile& cloud, std::size_t step);

}  // namespace cloudshape::io
