#include "geometry/circle.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "geometry/plane.hpp"

namespace cloudshape::geometry {
namespace {

constexpr int kGaussNewtonIterations = 15;

// Gauss-Newton on r_i = |p_i - c| - R for a point set in D dimensions, from an
// algebraic (Kasa) start: the algebraic fit is biased on arcs, the geometric one is not.
template <int D>
bool fit_hypersphere(const std::vector<Eigen::Matrix<double, D, 1>>& pts,
                     Eigen::Matrix<double, D, 1>& center, double& radius) {
  using Vec = Eigen::Matrix<double, D, 1>;
  const std::size_t n = pts.size();
  Eigen::MatrixXd a(n, D + 1);
  Eigen::VectorXd b(n);
  for (std::size_t i = 0; i < n; ++i) {
    a.row(i).head<D>() = pts[i].transpose();
    a(i, D) = 1.0;
    b(i) = -pts[i].squaredNorm();
  }
  const Eigen::VectorXd sol = a.colPivHouseholderQr().solve(b);
  center = -0.5 * sol.head<D>();
  const double r2 = center.squaredNorm() - sol(D);
  if (!(r2 > 0.0) || !std::isfinite(r2)) return false;
  radius = std::sqrt(r2);

  for (int it = 0; it < kGaussNewtonIterations; ++it) {
    Eigen::Matrix<double, D + 1, D + 1> jtj = Eigen::Matrix<double, D + 1, D + 1>::Zero();
    Eigen::Matrix<double, D + 1, 1> jtr = Eigen::Matrix<double, D + 1, 1>::Zero();
    for (const Vec& p : pts) {
      const Vec diff = p - center;
      const double dist = diff.norm();
      if (dist < 1e-15) continue;
      Eigen::Matrix<double, D + 1, 1> j;
      j.template head<D>() = -diff / dist;
      j(D) = -1.0;
      const double r = dist - radius;
      jtj.noalias() += j * j.transpose();
      jtr.noalias() += j * r;
    }
    const Eigen::Matrix<double, D + 1, 1> step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) return false;
    center += step.template head<D>();
    radius += step(D);
    if (step.norm() < 1e-12 * (radius + 1.0)) break;
  }
  return radius > 0.0 && std::isfinite(radius) && center.allFinite();
}

}  // namespace

std::optional<Circle3> circumcircle(const Point& a, const Point& b, const Point& c) {
  const Eigen::Vector3d t = b - a;
  const Eigen::Vector3d u = c - a;
  const Eigen::Vector3d txu = t.cross(u);
  const double denom = 2.0 * txu.squaredNorm();
  if (!(denom > 1e-24 * std::pow(t.squaredNorm() + u.squaredNorm(), 2))) return std::nullopt;
  Circle3 out;
  out.center = a + (u.squaredNorm() * txu.cross(t) + t.squaredNorm() * u.cross(txu)) / denom;
  out.radius = (out.center - a).norm();
  out.normal = txu.normalized();
  return out;
}

std::optional<Circle3> fit_circle_in_plane(const PointList& points,
                                           const std::vector<std::uint32_t>& indices,
                                           const Point& origin, const Eigen::Vector3d& normal) {
  if (indices.size() < 3) return std::nullopt;
  Eigen::Vector3d u, v;
  plane_basis(normal, u, v);
  std::vector<Eigen::Vector2d> pts;
  pts.reserve(indices.size());
  for (std::uint32_t i : indices) {
    const Eigen::Vector3d d = points[i] - origin;
    pts.emplace_back(d.dot(u), d.dot(v));
  }
  Eigen::Vector2d c;
  double r = 0.0;
  if (!fit_hypersphere<2>(pts, c, r)) return std::nullopt;
  Circle3 out;
  out.center = origin + c.x() * u + c.y() * v;
  out.normal = normal.normalized();
  out.radius = r;
  return out;
}

std::optional<SphereFit> fit_sphere(const PointList& points,
                                    const std::vector<std::uint32_t>& indices) {
  if (indices.size() < 4) return std::nullopt;
  std::vector<Eigen::Vector3d> pts;
  pts.reserve(indices.size());
  for (std::uint32_t i : indices) pts.push_back(points[i]);
  SphereFit out;
  if (!fit_hypersphere<3>(pts, out.center, out.radius)) return std::nullopt;
  double sum = 0.0;
  for (const auto& p : pts) sum += std::pow((p - out.center).norm() - out.radius, 2);
  out.rms = std::sqrt(sum / static_cast<double>(pts.size()));
  return out;
}

std::optional<SphereFit> fit_sphere(const PointList& points) {
  std::vector<std::uint32_t> all(points.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
  return fit_sphere(points, all);
}

}  // namespace cloudshape::geometry
