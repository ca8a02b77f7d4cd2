#include <cmath>

#include "geometry/circle.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::optional<FittedSolid> fit_cylinder(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * kPi / 180.0);
  // Caps: two faces facing opposite ways; else the largest face; else no cap is seen and
  // the side's normals give the axis.
  std::vector<const DetectedPlane*> caps;
  for (std::size_t a = 0; a < faces.size() && caps.empty(); ++a)
    for (std::size_t b = a + 1; b < faces.size() && caps.empty(); ++b)
      if (faces[a]->plane.normal.dot(faces[b]->plane.normal) < -cos_parallel)
        caps = {faces[a], faces[b]};
  if (caps.empty() && !faces.empty()) caps = {faces[0]};
  const auto side = detail::points_off_faces(in.cloud, caps);
  if (side.size() < 6) return std::nullopt;
  const Eigen::Vector3d axis =
      caps.empty() ? detail::axis_from_normals(in.cloud, side) : caps[0]->plane.normal;

  Point centroid = Point::Zero();
  for (std::uint32_t i : side) centroid += in.cloud[i];
  centroid /= static_cast<double>(side.size());
  const auto circle = geometry::fit_circle_in_plane(in.cloud, side, centroid, axis);
  if (!circle) return std::nullopt;
  const Point on_axis = circle->center;

  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Point& p : in.cloud) {
    lo = std::min(lo, (p - on_axis).dot(axis));
    hi = std::max(hi, (p - on_axis).dot(axis));
  }
  for (const DetectedPlane* cap : caps) {
    const double pos = detail::face_position(in.cloud, *cap, axis) - on_axis.dot(axis);
    if (cap->plane.normal.dot(axis) > 0) hi = pos;
    else lo = pos;
  }
  FittedSolid out;
  out.shape = Shape::cylinder;
  const double radius = circle->radius, height = hi - lo;
  out.dimensions = {{"radius", radius}, {"height", height}};
  out.center = on_axis + 0.5 * (lo + hi) * axis;
  out.axes = detail::frame_from_axis(axis);
  const Point c = out.center;
  out.signed_distance = [c, axis, radius, height](const Point& p) {
    const Eigen::Vector3d d = p - c;
    const double h = d.dot(axis);
    return std::max((d - h * axis).norm() - radius, std::abs(h) - 0.5 * height);
  };
  return out;
}

}  // namespace cloudshape::pipeline
