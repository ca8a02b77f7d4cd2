// Truncated right circular cone: a seen cap fixes the axis, the straight side its two radii,
// the other cap (or, unseen, where the side ends) its height.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "geometry/circle.hpp"
#include "pipeline/cylinder_refine.hpp"
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

// Radii a frustum may have: a taper too slight is a cylinder's, an end too small a cone's apex.
bool frustum_radii(const SolveInput& in, double radius, double top_radius) {
  return top_radius > in.cfg.frustum_min_top_share * radius && radius - top_radius > in.cfg.frustum_min_taper * radius;
}

// No rim's face seen (a single view of the side alone): the side fitted to the points alone
// (SolveInput::side_cone), its ends where the points end along the axis.
std::optional<FittedSolid> fit_frustum_from_side(const SolveInput& in) {
  const auto& side = in.side_cone();
  if (!side) return std::nullopt;
  const detail::SideCone& cone = side->cone;
  const double r_lo = cone.radius + cone.slope * side->lo,
               r_hi = cone.radius + cone.slope * side->hi;
  const double radius = std::max(r_lo, r_hi), top_radius = std::min(r_lo, r_hi);
  if (!frustum_radii(in, radius, top_radius)) return std::nullopt;
  const double height = side->hi - side->lo;
  FittedSolid out = r_lo >= r_hi ? make_frustum(cone.on_axis + side->lo * cone.axis, cone.axis,
                                                radius, top_radius, height)
                                 : make_frustum(cone.on_axis + side->hi * cone.axis, -cone.axis,
                                                radius, top_radius, height);
  // Free of any face, the fit has the second chance's freedom and must clear its bar.
  if (detail::explained_share(in, out) < in.cfg.side_fit_min_inlier_fraction) return std::nullopt;
  return out;
}

std::optional<FittedSolid> fit_frustum_on_cap(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  if (faces.empty()) return std::nullopt;
  const DetectedPlane* cap =
      in.classification.cap_plane ? &in.planes.planes[*in.classification.cap_plane] : faces[0];
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
  const double far =
      other ? detail::face_position(in.cloud, *other, side->axis) - side->centre.dot(side->axis)
            : side->top;
  if (!(far > 0.0)) return std::nullopt;
  const double near_radius = side->radius, far_radius = side->radius - side->slope * far;
  const double radius = std::max(near_radius, far_radius),
               top_radius = std::min(near_radius, far_radius);
  if (!frustum_radii(in, radius, top_radius)) return std::nullopt;
  if (near_radius >= far_radius)
    return make_frustum(side->centre, side->axis, radius, top_radius, far);
  return make_frustum(side->centre + far * side->axis, -side->axis, radius, top_radius, far);
}

// The side's axis from its normals, then axis, axis point, radius and taper refined together on
// the side points; the ends where the points end along the axis.
std::optional<detail::SideConeExtent> fit_side_cone(const SolveInput& in) {
  const auto& samples = in.cloud_normals();
  if (samples.size() < 20) return std::nullopt;
  std::vector<std::uint32_t> side(in.cloud.size());
  std::iota(side.begin(), side.end(), 0u);
  // Two starts: the second chance's cylinder (its axis refined on the side; a slight taper), and
  // the cone the side's tangent planes meet in (a strong one; a slight one's apex is ill placed).
  // The fit on more points within its band wins.
  std::vector<detail::SideCone> starts;
  if (const auto& cylinder = in.side_normals_cylinder())
    starts.push_back({cylinder->center, cylinder->axes.row(0).transpose(), cylinder->dimensions[0].second, 0.0});
  if (const auto cone = detail::cone_without_base(in)) {
    const double radius = cone->dimensions[0].second, height = cone->dimensions[1].second;
    if (radius > 0.0 && height > 0.0) starts.push_back({cone->center, cone->axes.row(0).transpose(), radius, -radius / height});
  }
  const double band = in.cfg.cylinder_refine_band * in.resolution;
  std::optional<detail::SideCone> cone;
  std::size_t cone_near = 0;
  // Six parameters need no ten thousand points: the refinement runs on at most
  // cfg.frustum_side_samples of them, evenly strided over the cloud (its Gauss-Newton steps pass
  // over every point they are given, 2 x 15 times per start: a third of a cylindric Kinect frame).
  const auto budget = static_cast<std::size_t>(std::max<std::int64_t>(0, in.cfg.frustum_side_samples));
  const std::size_t stride = budget == 0 ? 1 : std::max<std::size_t>(1, (side.size() + budget - 1) / budget);
  std::vector<std::uint32_t> fit_side;
  fit_side.reserve(side.size() / stride + 1);
  for (std::size_t i = 0; i < side.size(); i += stride) fit_side.push_back(side[i]);
  for (const detail::SideCone& start : starts) {
    const auto fit = detail::refine_side_cone(in.cloud, fit_side, start, std::max(band, 0.25 * start.radius), band,
                                              static_cast<int>(in.cfg.cylinder_refine_iterations));
    if (!fit) continue;
    std::size_t near = 0;
    for (const Point& p : in.cloud) near += std::abs(detail::side_distance(*fit, p)) <= band;
    if (!cone || near > cone_near) cone = fit, cone_near = near;
  }
  // Seen over a narrow arc (a flat-looking strip, a dark can full of holes) a side fixes no taper:
  // the same arc a cylinder from its side alone needs.
  if (!cone || detail::side_arc_degrees(in.cloud, side, *cone, in.cfg.inlier_distance * in.resolution) <
                   in.cfg.min_side_arc_degrees)
    return std::nullopt;
  std::vector<double> along;
  along.reserve(side.size());
  for (const Point& p : in.cloud) along.push_back((p - cone->on_axis).dot(cone->axis));
  const std::size_t trim = along.size() / 500;
  std::nth_element(along.begin(), along.begin() + trim, along.end());
  const double lo = along[trim];
  std::nth_element(along.begin(), along.end() - 1 - trim, along.end());
  const double hi = along[along.size() - 1 - trim];
  if (!(hi > lo)) return std::nullopt;
  // The taper is read along the height: the side must be seen along it, not on a few scan lines.
  constexpr int kStretches = 10;
  std::array<std::size_t, kStretches> per_stretch{};
  for (const Point& p : in.cloud) {
    const double t = ((p - cone->on_axis).dot(cone->axis) - lo) / (hi - lo);
    if (t >= 0.0 && t < 1.0) ++per_stretch[static_cast<std::size_t>(t * kStretches)];
  }
  int filled = 0;
  for (std::size_t n : per_stretch) filled += static_cast<double>(n) >= 0.005 * static_cast<double>(in.cloud.size());
  if (filled < in.cfg.frustum_side_fill * kStretches) return std::nullopt;
  return detail::SideConeExtent{*cone, lo, hi};
}

}  // namespace

const std::optional<detail::SideConeExtent>& SolveInput::side_cone() const {
  std::call_once(side_cone_once_, [this] { side_cone_ = fit_side_cone(*this); });
  return side_cone_;
}

std::optional<FittedSolid> fit_frustum(const SolveInput& in) {
  // The largest flat face may be a flat-looking strip of the side, taken for a rim's face: the
  // side's own fit is tried as well, and wins where it explains clearly more points
  // (solve.preferred_margin); a rim seen places the end better.
  auto on_cap = fit_frustum_on_cap(in);
  auto from_side = fit_frustum_from_side(in);
  if (!on_cap || !from_side) return on_cap ? on_cap : from_side;
  return detail::explained_share(in, *from_side) > detail::explained_share(in, *on_cap) + in.cfg.preferred_margin ? from_side : on_cap;
}

}  // namespace cloudshape::pipeline
