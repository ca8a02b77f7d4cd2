// Where a cloud is sampled along lines (the rings of a multi-beam lidar): normals of neighbourhoods
// grown until they span a surface, and edges that join a ring to the next across the gap.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::segment {

// Nodes whose cfg.normal_neighbours nearest nodes spread less than cfg.line_spread across
// (`linear_knn`) double their neighbourhood, up to cfg.line_max_neighbours nodes, until it spreads
// that much; normal and curvature then come from it (a node still on a line, a pole, keeps its
// own). Nodes whose graph neighbours lie on a line through them (`line_of[n]`, the line's unit
// direction, non-zero) get an edge to their nearest node more than 45 degrees off that line, within
// the same neighbourhood limit: the next ring, which no voxel neighbourhood reaches where rings lie
// farther apart than a voxel. Returns those edges (node, node off its line).
std::vector<std::pair<std::uint32_t, std::uint32_t>> widen_line_neighbourhoods(
    const PointList& nodes, const std::vector<char>& linear_knn, const std::vector<Eigen::Vector3d>& line_of,
    const config::SegmentConfig& cfg, std::vector<Eigen::Vector3d>& normals, std::vector<double>& curvature);

}  // namespace cloudshape::segment
