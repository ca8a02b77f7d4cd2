// Helpers over one plane's inliers seen in the plane's own 2-D frame: a raster for
// connectivity and border cells, and the curvature test that tells faces from strips.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/plane.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::pipeline::detail {

struct PatchRaster {
  std::vector<std::uint32_t> largest;          // inliers of the largest 8-connected component
  std::vector<std::uint32_t> border_candidates;  // those of them in cells with an empty neighbour
};

// Rasterises the projected inliers with square cells of edge `cell`, keeps the largest
// 8-connected component and marks the points lying in its border cells.
PatchRaster rasterise_patch(const PointList& cloud, const std::vector<std::uint32_t>& inliers,
                            const geometry::Plane& plane, double cell);

struct PatchCurvature {
  // Peak-to-peak deviation from the best plane of a least-squares quadric fitted to the
  // inliers: ~0 for a flat face (whatever the noise), ~the RANSAC band for a strip cut
  // from a curved surface.
  double sagitta = 0.0;
  // The quadric's smallest radius of curvature divided by the patch's extent in that
  // direction. A strip is only as wide as the band allows (about sqrt(8 R band)), which
  // keeps this near sqrt(R / 8 band): ~3 at the point budgets used. A gently bulging real
  // face (a cardboard box) curves over a radius many times its own width.
  double radius_to_extent = std::numeric_limits<double>::infinity();
};

PatchCurvature measure_patch_curvature(const PointList& cloud,
                                       const std::vector<std::uint32_t>& inliers,
                                       const geometry::Plane& plane);

}  // namespace cloudshape::pipeline::detail
