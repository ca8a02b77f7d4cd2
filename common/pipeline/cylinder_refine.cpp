#include "pipeline/cylinder_refine.hpp"

#include <array>
#include <cmath>

#include "geometry/plane.hpp"

namespace cloudshape::pipeline::detail {
namespace {

// normal_eq += w j j^T on and below the diagonal only, each entry as the full outer product
// computes it (j_c (w j_r)); the solver reads no more, and the upper half is mirrored from it.
template <int N>
void add_weighted_outer(Eigen::Matrix<double, N, N>& normal_eq, const Eigen::Matrix<double, N, 1>& j, double w) {
  const Eigen::Matrix<double, N, 1> wj = w * j;
  for (int c = 0; c < N; ++c)
    for (int r = c; r < N; ++r) normal_eq(r, c) += j(c) * wj(r);
}

template <int N>
void mirror_lower(Eigen::Matrix<double, N, N>& m) {
  m.template triangularView<Eigen::StrictlyUpper>() = m.transpose();
}

}  // namespace

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
      add_weighted_outer(normal_eq, j, w);
      rhs += w * j * r;
      ++used;
    }
    if (used < 6) return start;
    mirror_lower(normal_eq);
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

namespace {

// A point against a cone's side: its offset d from the axis point, height h along the axis,
// radial part q (length rho), and distance from the side (signed: outside positive).
struct SideOffset {
  Eigen::Vector3d d, q;
  double h, rho, distance;
};

// `norm`: sqrt(1 + slope^2), the same for every point of one cone.
SideOffset side_offset(const SideCone& c, const Point& p, double norm) {
  SideOffset o;
  o.d = p - c.on_axis;
  o.h = o.d.dot(c.axis);
  o.q = o.d - o.h * c.axis;
  o.rho = o.q.norm();
  o.distance = (o.rho - c.radius - c.slope * o.h) / norm;
  return o;
}

double slope_norm(const SideCone& c) { return std::sqrt(1.0 + c.slope * c.slope); }

// One Tukey-weighted Gauss-Newton run of the cone's side distance; nothing when it fails.
std::optional<SideCone> cone_steps(const PointList& cloud, const std::vector<std::uint32_t>& side,
                                   SideCone cur, double band, int iterations) {
  for (int it = 0; it < iterations; ++it) {
    Eigen::Vector3d u, v;
    geometry::plane_basis(cur.axis, u, v);
    double mean_h = 0.0;
    for (std::uint32_t i : side) mean_h += (cloud[i] - cur.on_axis).dot(cur.axis);
    mean_h /= static_cast<double>(side.size());
    cur.on_axis += mean_h * cur.axis;
    cur.radius += cur.slope * mean_h;
    // Parameters: axis tilt towards u and v, axis point moved along u and v, radius, slope.
    Eigen::Matrix<double, 6, 6> normal_eq = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    std::size_t used = 0;
    const double norm = slope_norm(cur);
    for (std::uint32_t i : side) {
      const SideOffset o = side_offset(cur, cloud[i], norm);
      const Eigen::Vector3d& d = o.d;
      const Eigen::Vector3d& q = o.q;
      const double h = o.h, rho = o.rho, r = o.distance;
      if (!(rho > 0.0) || std::abs(r) >= band) continue;
      const double t = 1.0 - (r / band) * (r / band);
      const double w = t * t;
      const Eigen::Vector3d n = q / rho;
      Eigen::Matrix<double, 6, 1> j;
      j << -h * n.dot(u) - cur.slope * d.dot(u), -h * n.dot(v) - cur.slope * d.dot(v), -n.dot(u),
          -n.dot(v), -1.0, -h;
      add_weighted_outer(normal_eq, j, w);
      rhs += w * j * (r * norm);
      ++used;
    }
    if (used < 8) return std::nullopt;
    mirror_lower(normal_eq);
    const Eigen::Matrix<double, 6, 1> step = -normal_eq.ldlt().solve(rhs);
    if (!step.allFinite()) return std::nullopt;
    cur.axis = (cur.axis + step[0] * u + step[1] * v).normalized();
    cur.on_axis += step[2] * u + step[3] * v;
    cur.radius += step[4];
    cur.slope += step[5];
    if (!(cur.radius > 0.0)) return std::nullopt;
    if (step.segment<3>(2).norm() < 1e-3 * band && step.head<2>().norm() < 1e-6 &&
        std::abs(step[5]) < 1e-6)
      break;
  }
  return cur;
}

}  // namespace

std::optional<SideCone> refine_side_cone(const PointList& cloud,
                                         const std::vector<std::uint32_t>& side,
                                         const SideCone& start, double loose_band, double band,
                                         int iterations) {
  if (side.size() < 8 || !(band > 0.0) || !(loose_band >= band) || !(start.radius > 0.0))
    return std::nullopt;
  const auto loose = cone_steps(cloud, side, start, loose_band, iterations);
  return loose ? cone_steps(cloud, side, *loose, band, iterations) : std::nullopt;
}

double side_distance(const SideCone& c, const Point& p) { return side_offset(c, p, slope_norm(c)).distance; }

double side_arc_degrees(const PointList& cloud, const std::vector<std::uint32_t>& side, const SideCylinder& c,
                        double band) {
  return side_arc_degrees(cloud, side, SideCone{c.on_axis, c.axis, c.radius, 0.0}, band);
}

double side_arc_degrees(const PointList& cloud, const std::vector<std::uint32_t>& side, const SideCone& c,
                        double band) {
  constexpr int kSectors = 36;
  constexpr double kPi = 3.14159265358979323846;
  Eigen::Vector3d u, v;
  geometry::plane_basis(c.axis, u, v);
  std::array<std::size_t, kSectors> count{};
  std::size_t near = 0;
  const double norm = slope_norm(c);
  for (std::uint32_t i : side) {
    const SideOffset o = side_offset(c, cloud[i], norm);
    if (std::abs(o.distance) > band) continue;
    const double a = std::atan2(o.q.dot(v), o.q.dot(u)) + kPi;
    ++count[static_cast<std::size_t>(std::min(kSectors - 1.0, a / (2.0 * kPi) * kSectors))];
    ++near;
  }
  int covered = 0;
  for (std::size_t n : count)
    if (near > 0 && static_cast<double>(n) >= 0.01 * static_cast<double>(near)) ++covered;
  return 360.0 / kSectors * covered;
}

}  // namespace cloudshape::pipeline::detail
