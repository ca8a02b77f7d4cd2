// Support-plane removal for real scenes: the table or floor the objects stand on is one big
// plane reaching well beyond them; it is cut away before the cloud is split into objects.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/plane.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::pipeline {

// The plane through the most points (RANSAC: `iterations` random triples, each scored on about
// `score_samples` points within `band`), refitted by least squares to all points within `band`.
// With `normals` (one per point), a point counts only where its own normal is within
// acos(min_cos) of the plane's. nullopt when no triple spans a plane.
std::optional<geometry::Plane> dominant_plane(const PointList& points, double band, std::int64_t iterations,
                                              std::int64_t score_samples, std::uint64_t seed,
                                              const std::vector<Eigen::Vector3d>* normals = nullptr,
                                              double min_cos = 0.0);

// Extents of points[idx] projected on u and v: {lo_u, hi_u, lo_v, hi_v}.
std::array<double, 4> footprint(const PointList& points, const std::vector<std::uint32_t>& idx,
                                const Eigen::Vector3d& u, const Eigen::Vector3d& v);

// True when the plane's footprint reaches beyond the objects' by `margin` times their extent
// on at least three of its four sides (the image border may crop a table on the fourth). A
// solid's own face reaches beyond the rest on one side at most: the solid's other faces end
// at its edges, and in a single view the visible ones line one or two of its edges.
bool surrounds(const std::array<double, 4>& plane, const std::array<double, 4>& objects, double margin);

// Finds the dominant plane (RANSAC over the whole cloud, band cfg.support_band resolutions)
// and removes it when it is a support: it holds at least cfg.support_min_share of the points,
// at least 80% of the other points stand on one side of it, and it reaches beyond their
// footprint on three of four sides by cfg.support_margin of their extent (a solid's own face ends
// where its other faces do), and at most cfg.support_max_overlap of
// them lie over where the plane was seen (a solid's face lies under the rest of the solid;
// a table is hidden where the objects stand on it). Then only those points are returned (the plane and whatever lies
// below it are gone); otherwise the cloud as it is. *removed, when given, says which.
PointList remove_support_plane(const PointList& points, double resolution,
                               const config::PreprocessConfig& cfg, bool* removed = nullptr);

}  // namespace cloudshape::pipeline
