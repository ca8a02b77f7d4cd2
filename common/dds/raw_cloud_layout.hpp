// The sensor layout a raw cloud carries (RawCloud width, height, pixel), checked before any
// use: a sender's layout is input like its coordinates, and segmentation indexes images by it.
#pragma once

#include <cstddef>

#include "cloudshape.h"
#include "config/stage_configs.hpp"
#include "dds/raw_cloud_error.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::dds {

// The layout of the sample's `points` points (NaN ones included): empty (unorganized) when
// pixel is empty and height is 0 or 1. Throws RawCloudError for pixels without height > 1, a
// width of 0, a grid of more pixels than limits.max_points or 32-bit indices address, a pixel
// count other than `points`, a pixel outside the grid or pixels not strictly increasing.
GridLayout raw_cloud_layout(const msg::RawCloud& cloud, std::size_t points, const config::InputConfig& limits);

}  // namespace cloudshape::dds
