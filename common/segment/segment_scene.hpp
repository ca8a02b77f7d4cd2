// Scene segmentation, one pure function from a cloud to its objects: the same path for a lone
// solid, several apart, and a cluttered table-top or lidar scene (organized clouds keep their grid).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"
#include "segment/structure_planes.hpp"

namespace cloudshape::segment {

struct SceneSegmentation {
  // Per object, indices into the input points, largest object first.
  std::vector<std::vector<std::uint32_t>> objects;
  // Per object, in a lidar frame, the scan lines (beams) its points lie on; 0 elsewhere.
  std::vector<std::uint32_t> scan_lines;
  std::vector<StructurePlane> structure;  // tables, floors, walls removed
  std::optional<Point> viewpoint;         // the sensor's position, when the layout tells it
  bool camera_view = false;  // an unorganized depth camera's frame (viewpoint: the origin)
  std::size_t graph_nodes = 0;            // nodes of the first graph of the cloud (in a lidar frame a finer one may follow)
  bool lone_solid = false;  // segmented as one solid with no support in view (the isolated trial)
  // An organized cloud whose pixels' depth carries noise of its own (NeighbourGraph::noisy_pixels).
  bool noisy_pixels = false;
};

// The graph (pixel cells when grid.organized(), voxels otherwise), structure planes removed,
// convex segments; segments under cfg.min_object_nodes nodes or cfg.min_object_share of the
// nodes are clutter, narrow ones smaller than cfg.fragment_max_share of the largest are slivers
// (in a depth image only strips and those bordering another: cfg.fragment_min_elongation),
// and flat segments lying in a structure plane are leftovers of it. An unorganized lidar frame in
// its sensor's frame (scan_origin) sees from the origin, and its walls and ground seen from inside
// are structure too; in an unorganized cloud what the structure leaves is gridded anew when that
// is much finer (finer_remainder_graph), and in a lidar frame a segment whose own points would grid
// much finer is segmented again alone (finer_on_its_own), one under the node minimum too if it
// holds that many points, and a part of it there is an object when it holds that many points (a
// voxel there may hold several): each object at its own resolution; there an object
// on fewer than cfg.scan_object_min_beams beams, or with cfg.scan_leftover_share of its points in a
// structure plane's band, is a strip of ground or wall, dropped. An unorganized cloud with no
// support in view (no plane reaching cfg.structure_reach times beyond what stands on it) that comes
// out at cfg.isolated_target_nodes (or at the scene's own voxel, where that budget coarsens
// nothing) as one object leaving out fewer than cfg.min_object_nodes points is segmented there: a
// lone solid needs no finer graph; any other is segmented at the scene's
// budget, as without that trial. An unorganized scene in front of the camera's plane z = 0 whose
// first structure plane has the origin far on its open side is a depth camera's frame without its
// grid (camera_view): its normals face the origin and the depth image's rules of convex_segments
// hold. A `pool` builds the graph's normals on its threads: the same segments.
SceneSegmentation segment_scene(const PointList& points, const GridLayout& grid, const config::SegmentConfig& cfg,
                                parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::segment
