#include <algorithm>
#include <cmath>

#include "geometry/circle.hpp"
#include "pipeline/cylinder_refine.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Two normals closer than solve.parallel_degrees are parallel: this cosine.
double cos_parallel(const SolveInput& in) { return std::cos(in.cfg.parallel_degrees * kPi / 180.0); }

// The cylinder around `axis`: radius from the side (the points off every flat face across the
// axis), height from `caps` and the extreme points along the axis. With a circular cap's outline
// the axis passes through its centre, and only the radius is taken from the side: a narrow band
// of side seen from above is too short an arc to place the axis. The second chance's axis, from
// the side's normals alone (`free_axis`), is refined with the circle on the side points: normals
// of a small or noisy side place it a few degrees off, and a tilted axis explains a band only.
std::optional<FittedSolid> fit_around_axis(const SolveInput& in, const std::vector<const DetectedPlane*>& faces,
                                           const std::vector<const DetectedPlane*>& caps,
                                           const Eigen::Vector3d& start_axis, bool free_axis,
                                           const FaceOutline* cap_outline = nullptr) {
  Eigen::Vector3d axis = start_axis;
  // Every flat face across the axis is cap-like (a recessed lid, the top of a rim): none
  // of them belongs to the side the radius is fitted on.
  std::vector<const DetectedPlane*> across;
  for (const DetectedPlane* f : faces)
    if (std::abs(f->plane.normal.dot(axis)) > cos_parallel(in)) across.push_back(f);
  const auto side = detail::points_off_faces(in.cloud, across, in.cfg.cap_band * in.resolution);
  std::optional<geometry::Circle3> circle;
  if (side.size() >= 6) {
    Point centroid = Point::Zero();
    for (std::uint32_t i : side) centroid += in.cloud[i];
    centroid /= static_cast<double>(side.size());
    circle = geometry::fit_circle_in_plane(in.cloud, side, centroid, axis);
    if (circle && free_axis && !cap_outline) {
      const detail::SideCylinder refined = detail::refine_side_cylinder(
          in.cloud, side, {circle->center, axis, circle->radius}, in.cfg.cylinder_refine_band * in.resolution,
          static_cast<int>(in.cfg.cylinder_refine_iterations));
      // A flat face tangent to the cylinder fits it over a narrow arc only.
      if (detail::side_arc_degrees(in.cloud, side, refined, in.cfg.inlier_distance * in.resolution) <
          in.cfg.min_side_arc_degrees)
        return std::nullopt;
      axis = refined.axis;
      circle = geometry::Circle3{refined.on_axis, axis, refined.radius};
    }
  }
  if (cap_outline) {
    // The side's own circle where it agrees with the cap's (a wide arc places it best), else the
    // cap's centre with the side's median distance from it (a short arc places no centre).
    const geometry::Circle3 cap{cap_outline->center, axis, cap_outline->radius};
    const double agree = in.cfg.cap_circle_agreement * cap.radius;
    const auto off_axis = [&](const Point& p) {
      const Eigen::Vector3d d = p - cap.center;
      return (d - d.dot(axis) * axis).norm();
    };
    const double min_side = std::max(6.0, in.cfg.min_side_share * static_cast<double>(in.cloud.size()));
    const bool side_agrees =
        circle && off_axis(circle->center) <= agree && std::abs(circle->radius - cap.radius) <= agree;
    if (!side_agrees && static_cast<double>(side.size()) >= min_side) {
      circle = cap;
      std::vector<double> radial;
      radial.reserve(side.size());
      for (std::uint32_t i : side) {
        const Eigen::Vector3d d = in.cloud[i] - circle->center;
        radial.push_back((d - d.dot(axis) * axis).norm());
      }
      std::nth_element(radial.begin(), radial.begin() + radial.size() / 2, radial.end());
      circle->radius = radial[radial.size() / 2];
    } else if (!side_agrees) {
      circle = cap;
    }
  }
  if (!circle) return std::nullopt;
  const Point on_axis = circle->center;

  // Height: the caps, unless points stand clearly beyond a cap (a can's rim around a
  // recessed lid): the solid's height includes the rim. A trimmed extreme keeps single
  // stray points from counting.
  std::vector<double> along;
  along.reserve(in.cloud.size());
  for (const Point& p : in.cloud) along.push_back((p - on_axis).dot(axis));
  const std::size_t trim = along.size() / 500;
  std::nth_element(along.begin(), along.begin() + trim, along.end());
  const double extreme_lo = along[trim];
  std::nth_element(along.begin(), along.end() - 1 - trim, along.end());
  const double extreme_hi = along[along.size() - 1 - trim];
  double lo = extreme_lo, hi = extreme_hi;
  const double rim = in.cfg.rim_distance * in.resolution;
  std::vector<double> recessed;  // caps below a rim, along the axis from on_axis
  for (const DetectedPlane* cap : caps) {
    const double pos = detail::face_position(in.cloud, *cap, axis) - on_axis.dot(axis);
    const bool top = cap->plane.normal.dot(axis) > 0;
    const bool rimmed = top ? extreme_hi > pos + rim : extreme_lo < pos - rim;
    if (top) hi = rimmed ? extreme_hi : pos;
    else lo = rimmed ? extreme_lo : pos;
    if (rimmed) recessed.push_back(pos);
  }
  FittedSolid out;
  out.shape = Shape::cylinder;
  const double radius = circle->radius, height = hi - lo;
  out.dimensions = {{"radius", radius}, {"height", height}};
  out.center = on_axis + 0.5 * (lo + hi) * axis;
  out.axes = detail::frame_from_axis(axis);
  const Point c = out.center;
  // A lid recessed below its rim is surface too (inside the solid's envelope): its points
  // are explained by it, whether the rim is a real can's or the flying pixels of a Kinect lid.
  for (double& pos : recessed) pos -= 0.5 * (lo + hi);
  out.signed_distance = [c, axis, radius, height, recessed](const Point& p) {
    const Eigen::Vector3d d = p - c;
    const double h = d.dot(axis);
    const double radial = (d - h * axis).norm();
    double sd = std::max(radial - radius, std::abs(h) - 0.5 * height);
    if (sd < 0.0 && radial <= radius)
      for (double pos : recessed) sd = std::max(sd, -std::abs(h - pos));
    return sd;
  };
  return out;
}

}  // namespace

std::optional<FittedSolid> fit_cylinder(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  if (const auto& cls = in.classification; cls.cap_plane) {
    const DetectedPlane* cap = &in.planes.planes[*cls.cap_plane];
    std::vector<const DetectedPlane*> caps{cap};
    for (const DetectedPlane* f : faces)
      if (f->plane.normal.dot(cap->plane.normal) < -cos_parallel(in)) {
        caps.push_back(f);
        break;
      }
    return fit_around_axis(in, faces, caps, cap->plane.normal, false, &cls.cap_outline);
  }
  // Caps: two faces facing opposite ways; else the largest face; else no cap is seen and
  // the side's normals give the axis.
  std::vector<const DetectedPlane*> caps;
  for (std::size_t a = 0; a < faces.size() && caps.empty(); ++a)
    for (std::size_t b = a + 1; b < faces.size() && caps.empty(); ++b)
      if (faces[a]->plane.normal.dot(faces[b]->plane.normal) < -cos_parallel(in))
        caps = {faces[a], faces[b]};
  if (caps.empty() && !faces.empty()) caps = {faces[0]};
  const Eigen::Vector3d axis = caps.empty()
                                   ? detail::axis_from_normals(in.cloud_normals())
                                   : caps[0]->plane.normal;
  return fit_around_axis(in, faces, caps, axis, false);
}

std::optional<FittedSolid> fit_cylinder_from_side_normals(const SolveInput& in) {
  return fit_around_axis(in, detail::faces_by_size(in.planes), {}, detail::axis_from_normals(in.cloud_normals()), true);
}

const std::optional<FittedSolid>& SolveInput::side_normals_cylinder() const {
  std::call_once(side_normals_cylinder_once_, [this] { side_normals_cylinder_ = fit_cylinder_from_side_normals(*this); });
  return side_normals_cylinder_;
}

}  // namespace cloudshape::pipeline
