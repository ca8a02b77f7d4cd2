#include "pipeline/cylinder_refine.hpp"

#include <array>
#include <cmath>

#include "geometry/plane.hpp"

namespace cloudshape::pipeline::detail {

SideCylinder refine_side_cylinder(const PointList& cloud, const std::vector<std::uint32_t>& side,
                                  const SideCylinder& start, double band, int iterations) {
  if (side.size() < 6 || !(band > 0.0) || !(start.radius > 0.0)) return start;
  SideCylinder cur = start;
  for (int it = 0; it < iterations; ++it) {
    Eigen::Vector3d u, v;
    geometry::plane_basis(cur.axis, u, v);
    // The axis turns about the points' mean height on it, which keeps the axis steps and the
    // point steps apart.
    double mean_h = 0.0;
    for (std::uint32_t i : side) mean_h += (cloud[i] - cur.on_axis).dot(cur.axis);
    cur.on_axis += mean_h / static_cast<double>(side.size()) * cur.axis;
    // Parameters: axis tilt towards u and v, axis point moved along u and v, radius.
    Eigen::Matrix<double, 5, 5> normal_eq = Eigen::Matrix<double, 5, 5>::Zero();
    Eigen::Matrix<double, 5, 1> rhs = Eigen::Matrix<double, 5, 1>::Zero();
    std::size_t used = 0;
    for (std::uint32_t i : side) {
      const Eigen::Vector3d d = cloud[i] - cur.on_axis;
      const double h = d.dot(cur.axis);
      const Eigen::Vector3d q = d - h * cur.axis;
      const double rho = q.norm();
      const double r = rho - cur.radius;
      if (!(rho > 0.0) || std::abs(r) >= band) continue;
      const double t = 1.0 - (r / band) * (r / band);
      const double w = t * t;
      const Eigen::Vector3d n = q / rho;
      Eigen::Matrix<double, 5, 1> j;
      j << -h * n.dot(u), -h * n.dot(v), -n.dot(u), -n.dot(v), -1.0;
      normal_eq += w * j * j.transpose();
      rhs += w * j * r;
      ++used;
    }
    if (used < 6) return start;
    const Eigen::Matrix<double, 5, 1> step = -normal_eq.ldlt().solve(rhs);
    if (!step.allFinite()) return start;
    cur.axis = (cur.axis + step[0] * u + step[1] * v).normalized();
    cur.on_axis += step[2] * u + step[3] * v;
    cur.radius += step[4];
    if (!(cur.radius > 0.0)) return start;
    if (step.tail<3>().norm() < 1e-3 * band && step.head<2>().norm() < 1e-6) break;
  }
  return cur;
}

double side_arc_degrees(const PointList& cloud, const std::vector<std::uint32_t>& side, const SideCylinder& c,
                        double band) {
  constexpr int kSectors = 36;
  constexpr double kPi = 3.14159265358979323846;
  Eigen::Vector3d u, v;
  geometry::plane_basis(c.axis, u, v);
  std::array<std::size_t, kSectors> count{};
  std::size_t near = 0;
  for (std::uint32_t i : side) {
    const Eigen::Vector3d d = cloud[i] - c.on_axis;
    const Eigen::Vector3d q = d - d.dot(c.axis) * c.axis;
    if (std::abs(q.norm() - c.radius) > band) continue;
    const double a = std::atan2(q.dot(v), q.dot(u)) + kPi;
    ++count[static_cast<std::size_t>(std::min(kSectors - 1.0, a / (2.0 * kPi) * kSectors))];
    ++near;
  }
  int covered = 0;
  for (std::size_t n : count)
    if (near > 0 && static_cast<double>(n) >= 0.01 * static_cast<double>(near)) ++covered;
  return 360.0 / kSectors * covered;
}

}  // namespace cloudshape::pipeline::detail
