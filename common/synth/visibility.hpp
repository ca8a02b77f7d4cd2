// Single-view hidden-point removal, to turn a 360-degree sampling into what one camera sees.
// Method: a spherical z-buffer (cube-map binning of view directions), see visible_from.
#pragma once

#include "geometry/point_cloud.hpp"

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <random>

namespace cloudshape::synth {

// Keeps the points a pinhole camera at `camera` would see (approximately; see below).
//
// Method: a spherical z-buffer. Directions from the camera are binned on a cube map whose +z
// face looks at the cloud's centroid, so the object sits near that face's centre where bins are
// closest to square. The angular bin size is resolution / (distance of the nearest point), so
// `resolution` is the bin's width on the nearest surface. It must exceed the point spacing or
// back points leak through empty bins; visibility_resolution (3x the mean spacing, ~9 points
// per bin) is a good choice.
// A point survives if its distance is within a tolerance of its bin's nearest point. A fixed
// tolerance cannot both keep steep front surfaces (whose depth spread within a bin grows with
// the slope) and drop hidden surfaces just behind an edge, so the tolerance adapts:
//   base_tolerance * bin width + slope_tolerance * (front-depth step to the neighbouring bins,
//   summed over the two grid directions, each the smaller of its two one-sided steps so that
//   a silhouette jump on one side does not count as slope, and each capped at 3 bin widths so
//   a bin the sampling left empty cannot reveal what lies far behind it).
// Measured with the defaults: a sphere seen from 5 radii keeps ~92% of its visible cap (losses
// at the grazing rim) and nothing beyond it; a cube keeps ~5-7% hidden points in slivers just
// behind its silhouette edges; a back face one bin width or more behind is removed. Those
// slivers are why make_synthetic_cloud uses the exact test of solid_visibility.hpp instead;
// mesh clouds (no analytic surface) keep this z-buffer and its slivers.
// Throws std::invalid_argument if resolution is not positive.
PointList visible_from(const PointList& points, const Eigen::Vector3d& camera, double resolution,
                       double base_tolerance = 0.2, double slope_tolerance = 1.0);

// A resolution for visible_from suited to n points spread over `area`: 3x the mean spacing.
double visibility_resolution(double area, std::size_t n);

// Draws from `sample(m)` (m area-uniform surface points of a surface with total `area`) and
// keeps the visible ones, oversampling so the result has exactly n points where possible (fewer
// only when almost nothing is visible). Keeps the visible density uniform: the surplus is
// removed by uniform random subsampling.
PointList sample_visible(const std::function<PointList(std::size_t)>& sample, double area,
                         std::size_t n, const Eigen::Vector3d& camera, std::mt19937_64& rng);

// The same with any visibility filter (points in, the visible ones out) instead of the z-buffer.
PointList sample_visible(const std::function<PointList(std::size_t)>& sample,
                         const std::function<PointList(const PointList&)>& keep_visible,
                         std::size_t n, std::mt19937_64& rng);

}  // namespace cloudshape::synth
