// Where an object stands on or against a structure plane, the graph's cells at its foot hold points
// of both: an object's points over the plane's footprint, within its own noise band, are the plane's.
#pragma once

#include <cstdint>
#include <unordered_set>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "segment/neighbour_graph.hpp"
#include "segment/structure_planes.hpp"

namespace cloudshape::segment {

// A removed structure plane as its points showed it: the band its points lie in and the cells
// of the plane its nodes cover.
struct StructureFootprint {
  geometry::Plane plane;
  double band = 0.0;  // cfg.contact_noise_sigmas robust deviations of its points, at least cfg.contact_min_band node spacings
  double cell = 0.0;  // its nodes' median spacing
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY();  // in-plane axes
  std::unordered_set<std::uint64_t> cells;  // in-plane cells of `cell` holding one of its nodes
};

// The footprints of `planes`, which removed the nodes set in `removed` (each node goes to the
// plane nearest to it); the graph's node_of_point[i] is the node of points[i].
std::vector<StructureFootprint> structure_footprints(const PointList& points, const NeighbourGraph& graph,
                                                     const std::vector<char>& removed,
                                                     const std::vector<StructurePlane>& planes,
                                                     const config::SegmentConfig& cfg);

// Whether `p` lies within a footprint's band over one of its cells or their eight neighbours.
bool on_structure(const std::vector<StructureFootprint>& footprints, const Point& p);

}  // namespace cloudshape::segment
