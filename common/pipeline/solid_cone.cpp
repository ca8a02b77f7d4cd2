#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/circle.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

namespace {

FittedSolid make_cone(const Point& centre, const Eigen::Vector3d& axis, double radius, double height) {
  FittedSolid out;
  out.shape = Shape::cone;
  out.dimensions = {{"radius", radius}, {"height", height}};
  out.center = centre;
  out.interior = centre + 0.25 * height * axis;
  out.axes = detail::frame_from_axis(axis);
  const double slant = std::hypot(radius, height);
  out.signed_distance = [centre, axis, radius, height, slant](const Point& p) {
    const Eigen::Vector3d d = p - centre;
    const double h = d.dot(axis);
    const double r = (d - h * axis).norm();
    return std::max(-h, (r * height + h * radius - radius * height) / slant);
  };
  return out;
}

// Where the key-points say polyhedron (a box, tetrahedron or prism corner count), the cone is
// only a rival hypothesis: the fits that need the cloud's normals are not worth computing.
bool polyhedron_class(const SolveInput& in) {
  const auto& classes = in.classification.candidates;
  return !classes.empty() && polyhedron_by_corners(classes.front());
}

// A cone whose base is not seen (a single view, the base on the table). Every tangent
// plane of a cone passes through its apex, so the apex is the least-squares meeting point of
// the local tangent planes; seen from the apex, every surface point lies at the same angle
// from the axis, so the axis is the direction those unit vectors vary least along.
std::optional<FittedSolid> fit_cone_without_base(const SolveInput& in) {
  const auto& samples = in.cloud_normals();
  if (samples.size() < 20) return std::nullopt;
  // Iteratively reweighted: normals taken across a sharp rim, or from stray points, give
  // tangent planes that miss the apex by far; Cauchy weights let the consistent majority decide.
  std::vector<double> weight(samples.size(), 1.0);
  Point apex = Point::Zero();
  for (int iteration = 0; iteration < 8; ++iteration) {
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const Eigen::Matrix3d nn = weight[k] * samples[k].normal * samples[k].normal.transpose();
      a += nn;
      b += nn * samples[k].at;
    }
    // A cylinder's tangent planes share a direction: no single meeting point.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> conditioning(a);
    if (conditioning.eigenvalues()(0) < in.cfg.apex_conditioning * conditioning.eigenvalues()(2))
      return std::nullopt;
    apex = a.ldlt().solve(b);
    std::vector<double> miss(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k)
      miss[k] = std::abs(samples[k].normal.dot(apex - samples[k].at));
    std::vector<double> sorted = miss;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double scale = std::max(1.5 * sorted[sorted.size() / 2], in.resolution);
    for (std::size_t k = 0; k < samples.size(); ++k) weight[k] = 1.0 / (1.0 + std::pow(miss[k] / scale, 2));
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> dirs;
  for (const Point& p : in.cloud) {
    const Eigen::Vector3d d = p - apex;
    if (d.norm() < 2.0 * in.resolution) continue;
    dirs.push_back(d.normalized());
    mean += dirs.back();
  }
  if (dirs.size() < 20) return std::nullopt;
  mean /= static_cast<double>(dirs.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& d : dirs) cov.noalias() += (d - mean) * (d - mean).transpose();
  Eigen::Vector3d down = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
  if (down.dot(mean) < 0) down = -down;  // from the apex into the surface
  double cos_half = 0.0;
  for (const auto& d : dirs) cos_half += d.dot(down);
  cos_half /= static_cast<double>(dirs.size());
  if (!(cos_half > 0.0 && cos_half < 1.0)) return std::nullopt;
  std::vector<double> depth;
  for (const Point& p : in.cloud) depth.push_back((p - apex).dot(down));
  const std::size_t top = depth.size() - 1 - depth.size() / 500;
  std::nth_element(depth.begin(), depth.begin() + top, depth.end());
  const double height = depth[top];
  if (!(height > 0.0)) return std::nullopt;
  const double radius = height * std::tan(std::acos(cos_half));
  return make_cone(apex + height * down, -down, radius, height);
}

std::optional<FittedSolid> fit_cone_on_base(const SolveInput& in, const DetectedPlane& base) {
  const auto side = detail::fit_conical_side(in, base, {&base});
  if (!side || !(side->radius > 0.0) || !(side->slope > 0.0)) return std::nullopt;
  return make_cone(side->centre, side->axis, side->radius, side->radius / side->slope);
}

// How near the points come to the cone's apex.
double nearest_to_apex(const SolveInput& in, const FittedSolid& cone) {
  const Point apex = cone.center + cone.dimensions[1].second * cone.axes.row(0).transpose();
  double nearest = std::numeric_limits<double>::infinity();
  for (const Point& p : in.cloud) nearest = std::min(nearest, (p - apex).norm());
  return nearest;
}

double slant_height(const FittedSolid& cone) {
  return std::hypot(cone.dimensions[0].second, cone.dimensions[1].second);
}

// A cone cut short: no point comes within solve.apex_gap of the slant height of its apex, while
// the highest points ring the axis all round (a cut's rim; a cone seen from below shows only
// part of its silhouette there, a complete one its tip); or none within solve.cone_tip_gap,
// ringing it or not: a side seen at all reaches the tip, a frustum's seen from one side stops
// at part of its smaller rim.
bool cut_short(const SolveInput& in, const FittedSolid& cone) {
  const Eigen::Vector3d axis = cone.axes.row(0).transpose();
  const double height = cone.dimensions[1].second;
  const double nearest = nearest_to_apex(in, cone);
  if (nearest > in.cfg.cone_tip_gap * slant_height(cone)) return true;
  if (nearest <= in.cfg.apex_gap * slant_height(cone)) return false;
  double top = -std::numeric_limits<double>::infinity();
  for (const Point& p : in.cloud) top = std::max(top, (p - cone.center).dot(axis));
  const Eigen::Matrix3d frame = cone.axes;
  std::array<bool, 12> sector{};
  const double slab = std::max(in.cfg.face_slab * height, 2.0 * in.resolution);
  for (const Point& p : in.cloud) {
    const Eigen::Vector3d d = p - cone.center;
    if (d.dot(axis) < top - slab) continue;
    const double a = std::atan2(d.dot(frame.row(2).transpose()), d.dot(frame.row(1).transpose()));
    sector[static_cast<std::size_t>(std::clamp((a + 3.14159265358979323846) / (2.0 * 3.14159265358979323846) * 12.0, 0.0, 11.0))] = true;
  }
  return std::count(sector.begin(), sector.end(), true) >= 10;
}

// The largest flat face is taken for the base, but a single view may show no base at all,
// and then that "face" is a flat-looking strip of the side. A cone on it that explains too
// few points to be reported is not the answer: the base-free fit is tried as well, and the
// one explaining more points wins (only then: the base-free fit needs the cloud's normals).
std::optional<FittedSolid> fit_cone_any(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  std::optional<FittedSolid> on_base;
  if (!faces.empty()) on_base = fit_cone_on_base(in, *faces[0]);
  // A strip of the side taken for the base gives a cone far larger than the points: none.
  if (on_base && !detail::plausible(*on_base, 2.0 * in.keypoints.reference.radius, in.cfg.max_size_ratio))
    on_base.reset();
  const double on_base_share = on_base ? detail::explained_share(in, *on_base) : 0.0;
  if (polyhedron_class(in) || (on_base && on_base_share >= in.cfg.min_inlier_fraction))
    return on_base;
  std::optional<FittedSolid> free = fit_cone_without_base(in);
  if (!on_base || !free) return on_base ? on_base : free;
  return detail::explained_share(in, *free) > on_base_share ? free : on_base;
}

// The cone on the tapered side fitted to the points alone: its apex where the side's radius comes
// to nothing, its base where the points end at the wide end.
std::optional<FittedSolid> cone_on_side(const SolveInput& in) {
  const auto& side = in.side_cone();
  if (!side || side->cone.slope == 0.0) return std::nullopt;
  const detail::SideCone& c = side->cone;
  const double r_lo = c.radius + c.slope * side->lo, r_hi = c.radius + c.slope * side->hi;
  const bool wide_at_lo = r_lo >= r_hi;
  const double base = wide_at_lo ? side->lo : side->hi;
  const double radius = std::max(r_lo, r_hi);
  // Heights grow towards the apex from the base.
  const double height = (wide_at_lo ? 1.0 : -1.0) * (-c.radius / c.slope - base);
  if (!(radius > 0.0) || !(height > 0.0)) return std::nullopt;
  return make_cone(c.on_axis + base * c.axis, wide_at_lo ? c.axis : Eigen::Vector3d(-c.axis),
                   radius, height);
}

}  // namespace

std::optional<FittedSolid> detail::cone_without_base(const SolveInput& in) { return fit_cone_without_base(in); }

std::optional<FittedSolid> fit_cone(const SolveInput& in) {
  auto cone = fit_cone_any(in);
  if (cone && cut_short(in, *cone)) return std::nullopt;
  return cone;
}

std::optional<FittedSolid> cone_of_frustum(const FittedSolid& frustum) {
  if (frustum.shape != Shape::frustum || frustum.dimensions.size() < 3) return std::nullopt;
  const double radius = frustum.dimensions[0].second, top = frustum.dimensions[1].second;
  const double height = frustum.dimensions[2].second;
  if (!(radius > top) || !(height > 0.0)) return std::nullopt;
  return make_cone(frustum.center, frustum.axes.row(0).transpose(), radius,
                   height * radius / (radius - top));
}

std::optional<FittedSolid> cone_closing_frustum(const SolveInput& in, const FittedSolid& frustum) {
  std::optional<FittedSolid> cone = cone_of_frustum(frustum);
  if (cone && cut_short(in, *cone)) return std::nullopt;
  return cone;
}

std::optional<FittedSolid> fit_cone_from_side(const SolveInput& in) {
  auto cone = cone_on_side(in);
  if (!cone ||
      !detail::plausible(*cone, 2.0 * in.keypoints.reference.radius, in.cfg.max_size_ratio) ||
      nearest_to_apex(in, *cone) > in.cfg.apex_gap * slant_height(*cone) ||
      detail::explained_share(in, *cone) < in.cfg.side_fit_min_inlier_fraction)
    return std::nullopt;
  return cone;
}

}  // namespace cloudshape::pipeline
