#include <Eigen/Dense>
#include <cmath>
#include <complex>

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::optional<FittedSolid> fit_pentagonal_prism(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  if (faces.size() < 4) return std::nullopt;
  const double sin_perp = std::sin(in.cfg.perpendicular_degrees * kPi / 180.0);
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * kPi / 180.0);

  // The caps: the face whose normal is perpendicular to the most other faces.
  const DetectedPlane* cap = nullptr;
  std::vector<const DetectedPlane*> sides;
  for (const DetectedPlane* candidate : faces) {
    std::vector<const DetectedPlane*> perpendicular;
    for (const DetectedPlane* f : faces)
      if (std::abs(f->plane.normal.dot(candidate->plane.normal)) < sin_perp) perpendicular.push_back(f);
    if (perpendicular.size() > sides.size()) {
      sides = perpendicular;
      cap = candidate;
    }
  }
  if (!cap || sides.size() < 3) return std::nullopt;
  const Eigen::Vector3d axis = cap->plane.normal;
  const Eigen::Matrix3d frame = detail::frame_from_axis(axis);
  const Eigen::Vector3d u = frame.row(1).transpose(), v = frame.row(2).transpose();

  // Every side face sits at the same distance a (the apothem) from the axis: solve
  // n_k.(o + s u + t v) + d_k + a = 0 for the axis position (s, t) and a.
  const Point origin = in.cloud[cap->inliers.front()];
  Eigen::MatrixXd m(sides.size(), 3);
  Eigen::VectorXd rhs(sides.size());
  std::complex<double> orientation = 0.0;
  for (std::size_t k = 0; k < sides.size(); ++k) {
    const geometry::Plane& p = sides[k]->plane;
    m(k, 0) = p.normal.dot(u);
    m(k, 1) = p.normal.dot(v);
    m(k, 2) = 1.0;
    rhs(k) = -(p.normal.dot(origin) + p.offset);
    const double phi = std::atan2(p.normal.dot(v), p.normal.dot(u));
    orientation += static_cast<double>(sides[k]->inliers.size()) * std::polar(1.0, 5.0 * phi);
  }
  const Eigen::Vector3d sol = m.colPivHouseholderQr().solve(rhs);
  const double apothem = sol(2);
  if (!(apothem > 0.0) || !sol.allFinite()) return std::nullopt;
  const Point on_axis = origin + sol(0) * u + sol(1) * v;

  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Point& p : in.cloud) {
    lo = std::min(lo, (p - on_axis).dot(axis));
    hi = std::max(hi, (p - on_axis).dot(axis));
  }
  for (const DetectedPlane* f : faces) {
    const double c = f->plane.normal.dot(axis);
    if (std::abs(c) < cos_parallel) continue;
    const double pos = detail::face_position(in.cloud, *f, axis) - on_axis.dot(axis);
    if (c > 0) hi = pos;
    else lo = pos;
  }
  const double height = hi - lo;
  const double phi0 = std::arg(orientation) / 5.0;

  FittedSolid out;
  out.shape = Shape::pentagonal_prism;
  out.dimensions = {{"side", 2.0 * apothem * std::tan(kPi / 5.0)}, {"height", height}};
  out.center = on_axis + 0.5 * (lo + hi) * axis;
  const Eigen::Vector3d first_normal = std::cos(phi0) * u + std::sin(phi0) * v;
  out.axes.row(0) = axis.transpose();
  out.axes.row(1) = first_normal.transpose();
  out.axes.row(2) = axis.cross(first_normal).transpose();
  const Point c = out.center;
  out.signed_distance = [c, axis, u, v, phi0, apothem, height](const Point& p) {
    const Eigen::Vector3d d = p - c;
    double sd = std::abs(d.dot(axis)) - 0.5 * height;
    for (int j = 0; j < 5; ++j) {
      const double phi = phi0 + j * 2.0 * kPi / 5.0;
      sd = std::max(sd, d.dot(std::cos(phi) * u + std::sin(phi) * v) - apothem);
    }
    return sd;
  };
  return out;
}

}  // namespace cloudshape::pipeline
