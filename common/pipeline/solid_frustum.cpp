// Truncated right circular cone: a seen cap fixes the axis, the straight side its two radii,
// the other cap (or, unseen, where the side ends) its height.
#include <algorithm>
#include <cmath>

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;

FittedSolid make_frustum(const Point& base, const Eigen::Vector3d& axis, double radius, double top_radius,
                         double height) {
  FittedSolid out;
  out.shape = Shape::frustum;
  out.dimensions = {{"radius", radius}, {"top_radius", top_radius}, {"height", height}};
  out.center = base;
  out.interior = base + 0.5 * height * axis;
  out.axes = detail::frame_from_axis(axis);
  const double slope = (radius - top_radius) / height;
  const double norm = std::sqrt(1.0 + slope * slope);
  out.signed_distance = [base, axis, radius, height, slope, norm](const Point& p) {
    const Eigen::Vector3d d = p - base;
    const double h = d.dot(axis);
    const double r = (d - h * axis).norm();
    return std::max({-h, h - height, (r - (radius - slope * h)) / norm});
  };
  return out;
}

}  // namespace

std::optional<FittedSolid> fit_frustum(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  if (faces.empty()) return std::nullopt;
  const DetectedPlane* cap = in.classification.cap_plane ? &in.planes.planes[*in.classification.cap_plane] : faces[0];
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * kPi / 180.0);
  const DetectedPlane* other = nullptr;
  for (const DetectedPlane* f : faces)
    if (f->plane.normal.dot(cap->plane.normal) < -cos_parallel) {
      other = f;
      break;
    }
  std::vector<const DetectedPlane*> flat{cap};
  if (other) flat.push_back(other);
  const auto side = detail::fit_conical_side(in, *cap, flat);
  if (!side) return std::nullopt;
  // The far end: the other cap where it is seen, else where the side's points end.
  const double far = other ? detail::face_position(in.cloud, *other, side->axis) - side->centre.dot(side->axis)
                           : side->top;
  if (!(far > 0.0)) return std::nullopt;
  const double near_radius = side->radius, far_radius = side->radius - side->slope * far;
  const double radius = std::max(near_radius, far_radius), top_radius = std::min(near_radius, far_radius);
  // A taper too slight is a cylinder's, an end too small a cone's apex: neither is a frustum.
  if (!(top_radius > in.cfg.frustum_min_top_share * radius) ||
      !(radius - top_radius > in.cfg.frustum_min_taper * radius))
    return std::nullopt;
  if (near_radius >= far_radius) return make_frustum(side->centre, side->axis, radius, top_radius, far);
  return make_frustum(side->centre + far * side->axis, -side->axis, radius, top_radius, far);
}

}  // namespace cloudshape::pipeline
