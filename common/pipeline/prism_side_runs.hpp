// A prism's side faces as straight runs in its cross-section plane: each face's stretches (split
// where their points leave a gap), ordered around the outline, and joined where collinear.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline::detail {

// One straight stretch of a side face in the cross-section plane: the line n.x = d with n
// outward, its points between t_lo and t_hi along the counter-clockwise tangent (-n.y, n.x).
struct SideRun {
  Eigen::Vector2d n = Eigen::Vector2d::UnitX();
  double d = 0.0;
  double t_lo = 0.0, t_hi = 0.0;
  double weight = 0.0;  // points behind the line
  bool seen = true;     // a side face's; false for a side only a cap's border shows
  double hull_area = 0.0;  // of its points in the plane of the side and the axis
  Eigen::Vector2d tangent() const { return {-n.y(), n.x()}; }
  Eigen::Vector2d start() const { return d * n + t_lo * tangent(); }
  Eigen::Vector2d end() const { return d * n + t_hi * tangent(); }
};

// The side face's stretches in the cross-section (u, v: the plane across the axis): its points
// split where they leave a gap (two coplanar sides of a non-convex outline, such as a plus sign's
// arms, share one plane). The outward side is where the caps' points (`cap_points`, in u, v) are
// not; without a cap the plane's own normal (away from the cloud's centroid) stands, which is
// right for every convex outline. Points at a cap's height are left to the cap.
std::vector<SideRun> side_runs(const SolveInput& in, const DetectedPlane& face, const Eigen::Vector3d& u,
                               const Eigen::Vector3d& v, const std::vector<Eigen::Vector2d>& cap_points,
                               const std::vector<const DetectedPlane*>& caps);

// Orders the runs around the outline: from the largest, each run's end goes on to the nearest
// start of a run not yet taken, until that is the first run's again. Runs off the walk are left
// out; only a closed walk, every corner closer than `max_gap`, is an outline.
std::optional<std::vector<SideRun>> chain_runs(std::vector<SideRun> runs, double max_gap);

// Consecutive runs along one line (a side RANSAC cut in two) become one side; a side only a
// cap's border shows is placed less exactly: `loose_band` for it.
std::vector<SideRun> merge_collinear(std::vector<SideRun> ring, double cos_parallel, double band, double loose_band);

// Where the lines of two runs cross; nothing for parallel ones.
std::optional<Eigen::Vector2d> intersect(const SideRun& a, const SideRun& b);

}  // namespace cloudshape::pipeline::detail
