// Stage 2 (thesis 3.1): planes by iterative RANSAC, called with a coarse then a fine
// threshold; each plane's boundary points; the lines common to two planes.
#pragma once

#include <optional>

#include <cstdint>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/kdtree.hpp"
#include "geometry/plane.hpp"
#include "geometry/point_cloud.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::pipeline {

struct DetectedPlane {
  geometry::Plane plane;                // normal oriented away from the cloud's centroid
  std::vector<std::uint32_t> inliers;   // indices into the cloud
  std::vector<std::uint32_t> boundary;  // inliers on the border of the patch
  // A true flat face: the patch shows no curvature beyond the noise. False for the
  // tangent strips RANSAC cuts out of curved surfaces (thesis Fig. 4.3).
  bool is_face = false;
  double curvature_sagitta = 0.0;       // deviation of a quadric fit from the plane, in resolutions
  double curvature_radius_ratio = 0.0;  // the quadric's radius of curvature over the patch extent
};

struct PlaneLine {
  geometry::Line line;
  double t_min = 0.0;  // extent along line.direction where both planes' boundaries lie
  double t_max = 0.0;
  std::uint32_t plane_a = 0;
  std::uint32_t plane_b = 0;

  Point start() const { return line.point + t_min * line.direction; }
  Point end() const { return line.point + t_max * line.direction; }
};

struct PlaneSegmentation {
  std::vector<DetectedPlane> planes;
  std::vector<PlaneLine> lines;
  std::vector<std::int32_t> labels;  // per point: index of its plane, or -1
  // The points' noise along a depth camera's rays (noise_along_view), as read for the fine band;
  // 0 where it was not read (no viewpoint, or cfg.noise_sigmas 0). The solver reuses it.
  double view_noise = 0.0;
};

// `tree`, if given, is a search tree over `cloud` (the object's, shared by the stages). A `pool`
// shares the boundary tests out: the same result. `viewpoint`: a depth camera's, where known (the
// fine band then follows the points' noise along its rays, cfg.noise_sigmas); not a lidar's
// (noise_viewpoint).
PlaneSegmentation segment_planes(const PointList& cloud, double resolution,
                                 const config::PlanesConfig& cfg,
                                 const geometry::KdTree* tree = nullptr,
                                 parallel::ThreadPool* pool = nullptr,
                                 const std::optional<Point>& viewpoint = std::nullopt);

// Lines where two planes meet, clipped to where both planes' boundary points lie near.
std::vector<PlaneLine> find_plane_lines(const PointList& cloud,
                                        const std::vector<DetectedPlane>& planes,
                                        double resolution, const config::PlanesConfig& cfg);

// The `candidates` (points of plane `label`) on the border of their patch: points whose
// in-plane angular gap between neighbours of the same plane exceeds cfg.boundary_gap_degrees;
// in the candidates' order. A `pool` tests blocks of candidates on its threads: the same points.
std::vector<std::uint32_t> find_plane_boundary(const geometry::KdTree& tree,
                                               const std::vector<std::int32_t>& labels,
                                               std::int32_t label, const geometry::Plane& plane,
                                               const std::vector<std::uint32_t>& candidates,
                                               const config::PlanesConfig& cfg,
                                               parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::pipeline
