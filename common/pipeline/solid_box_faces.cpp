// What a box's faces must be beyond lying along its axes: none of its large neighbours meets one
// of them at a slant, and each bounds the points (a box is convex: no face of it is a step).
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/plane.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline::detail {
namespace {

double quantile(std::vector<double> v, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Faces `a` and `b` have points within `reach` of the line where their planes cross, over a
// common stretch of it longer than `reach` (a face the view or an occluder cuts has no neighbour
// there), and reach from it comparably far across: the narrower's width (2-98% of its points, in
// its plane across the line) is at least `width_ratio` of the wider's. Each side's width is that
// of every face parallel to it (`a_parallel`, `b_parallel`, a and b among them): noise splits a
// large face into coplanar pieces. Two sides of a prism are its height long and alike in width; a carton's gable
// or a strip noise cuts along a box's edge is far narrower than the face it leans on.
bool slanted_neighbours(const PointList& cloud, const DetectedPlane& a, const DetectedPlane& b,
                        const std::vector<const DetectedPlane*>& a_parallel,
                        const std::vector<const DetectedPlane*>& b_parallel, double reach, double width_ratio) {
  const auto line = geometry::intersect_planes(a.plane, b.plane);
  if (!line) return false;
  auto stretch = [&](const DetectedPlane& f) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::uint32_t i : f.inliers) {
      const Eigen::Vector3d v = cloud[i] - line->point;
      const double t = v.dot(line->direction);
      if ((v - t * line->direction).norm() > reach) continue;
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    return std::make_pair(lo, hi);
  };
  const auto [alo, ahi] = stretch(a);
  const auto [blo, bhi] = stretch(b);
  if (!(std::min(ahi, bhi) - std::max(alo, blo) > reach)) return false;
  auto width = [&](const std::vector<const DetectedPlane*>& set, const Eigen::Vector3d& normal) {
    const Eigen::Vector3d across = normal.cross(line->direction).normalized();
    std::vector<double> offsets;
    for (const DetectedPlane* f : set)
      for (std::uint32_t i : f->inliers) offsets.push_back((cloud[i] - line->point).dot(across));
    return offsets.empty() ? 0.0 : quantile(offsets, 0.98) - quantile(offsets, 0.02);
  };
  const double wa = width(a_parallel, a.plane.normal), wb = width(b_parallel, b.plane.normal);
  return std::min(wa, wb) >= width_ratio * std::max(wa, wb);
}

bool along_any(const Eigen::Vector3d& normal, const std::vector<Eigen::Vector3d>& directions, double cos_along) {
  for (const Eigen::Vector3d& d : directions)
    if (normal.dot(d) >= cos_along) return true;
  return false;
}

}  // namespace

bool slanted_neighbour_face(const SolveInput& in, const std::vector<const DetectedPlane*>& faces,
                            const std::vector<Eigen::Vector3d>& directions, double cos_along) {
  const double reach = in.cfg.box_edge_distance * in.resolution;
  // The two meet at a slant: off parallel and off square by acos(cos_along).
  const double sin_along = std::sqrt(std::max(0.0, 1.0 - cos_along * cos_along));
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * 3.14159265358979323846 / 180.0);
  auto parallel_to = [&](const DetectedPlane& f) {
    std::vector<const DetectedPlane*> set;
    for (const DetectedPlane* g : faces)
      if (g->plane.normal.dot(f.plane.normal) >= cos_parallel) set.push_back(g);
    return set;
  };
  for (const DetectedPlane* stray : faces) {
    if (along_any(stray->plane.normal, directions, cos_along)) continue;
    for (const DetectedPlane* f : faces)
      if (f != stray && std::abs(f->plane.normal.dot(stray->plane.normal)) < cos_along &&
          std::abs(f->plane.normal.dot(stray->plane.normal)) > sin_along && along_any(f->plane.normal, directions, cos_parallel) &&
          slanted_neighbours(in.cloud, *stray, *f, parallel_to(*stray), parallel_to(*f), reach,
                             in.cfg.box_slanted_width_ratio))
        return true;
  }
  return false;
}

double step_depth(const SolveInput& in, const Eigen::Vector3d& axis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Point& p : in.cloud) {
    lo = std::min(lo, p.dot(axis));
    hi = std::max(hi, p.dot(axis));
  }
  return std::max(in.cfg.box_step_depth * (hi - lo), in.cfg.inlier_distance * in.resolution);
}

bool piece_of_face(const PointList& cloud, const DetectedPlane& g, const Eigen::Vector3d& direction,
                   double at, double depth, double cos_along) {
  return g.plane.normal.dot(direction) >= cos_along &&
         std::abs(face_position(cloud, g, direction) - at) <= depth;
}

bool face_is_step(const SolveInput& in, const std::vector<const DetectedPlane*>& faces,
                  const std::vector<Eigen::Vector3d>& directions, double cos_along) {
  if (faces.empty()) return false;
  std::size_t all = 0;
  for (const DetectedPlane* f : faces) all += f->inliers.size();
  const double min_points = in.cfg.box_step_min_share * static_cast<double>(all);
  for (const DetectedPlane* f : faces) {
    if (static_cast<double>(f->inliers.size()) < min_points) continue;
    // The plane square to the box direction the face is along, through the face's points: a
    // piece of a real box's bulging face tilts by up to parallel_degrees, and its own plane then
    // runs through the faces square to it across a thin box (a cracker box's 6 cm side against
    // its 21 cm faces), on both sides by more than a tenth of that thickness.
    const Eigen::Vector3d* along = nullptr;
    for (const Eigen::Vector3d& d : directions)
      if (f->plane.normal.dot(d) >= cos_along &&
          (!along || f->plane.normal.dot(d) > f->plane.normal.dot(*along)))
        along = &d;
    if (!along) continue;
    const double depth = step_depth(in, *along);
    const double at = face_position(in.cloud, *f, *along);
    // Face points beyond the plane on either side: a bounding face has them all on one. The
    // face's own pieces are the face, and their bulge is no step.
    std::size_t above = 0, below = 0;
    for (const DetectedPlane* g : faces) {
      if (piece_of_face(in.cloud, *g, *along, at, depth, cos_along)) continue;
      for (std::uint32_t i : g->inliers) {
        const double d = in.cloud[i].dot(*along) - at;
        above += d > depth;
        below += d < -depth;
      }
    }
    if (static_cast<double>(std::min(above, below)) > in.cfg.box_step_share * static_cast<double>(all)) return true;
  }
  return false;
}

}  // namespace cloudshape::pipeline::detail
