// Where an object stands on or against a structure plane, the graph's cells at its foot hold points
// of both: an object's points over the plane's footprint, within its own noise band, are the plane's.
#pragma once

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "segment/detail/key_index.hpp"
#include "segment/neighbour_graph.hpp"
#include "segment/structure_planes.hpp"

namespace cloudshape::segment {

// A removed structure plane as its points showed it: the cells of the plane it covers, the height
// of its points above the plane in each, and the band they lie in about those heights.
struct StructureFootprint {
  geometry::Plane plane;
  double band = 0.0;  // cfg.contact_noise_sigmas robust deviations of its points about their cells' heights, at least cfg.contact_min_band node spacings
  double cell = 0.0;  // its nodes' median spacing
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY();  // in-plane axes
  detail::CellValues cells;  // in-plane cells of `cell` it covers, each with its points' height
  double lowest = 0.0, highest = 0.0;  // the cells' heights span this
};

// The footprints of `planes`, which removed the nodes set in `removed` (each node goes to the
// plane nearest to it); the graph's node_of_point[i] is the node of points[i]. The cells are
// those its nodes lie in, at height 0: a flat table or wall. With `cell_heights`, those the points
// of its nodes beside a node it left (the graph's neighbours; what stands on it) lie in, each at
// the median height of those points there: a ground or wall that is not flat (a lidar's real
// ground, tilted or rolling, over a wide scene) keeps a band as narrow as its noise, and its far
// reaches cost nothing.
std::vector<StructureFootprint> structure_footprints(const PointList& points, const NeighbourGraph& graph,
                                                     const std::vector<char>& removed,
                                                     const std::vector<StructurePlane>& planes,
                                                     const config::SegmentConfig& cfg, bool cell_heights = false);

// Whether `p` lies within a footprint's band about the height of one of its cells or their eight
// neighbours, over that cell.
bool on_structure(const std::vector<StructureFootprint>& footprints, const Point& p);

}  // namespace cloudshape::segment
