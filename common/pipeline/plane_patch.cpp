#include "pipeline/plane_patch.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "geometry/detail/flat_hash.hpp"
#include "geometry/detail/union_find.hpp"

namespace cloudshape::pipeline::detail {
namespace {

// Offsetting to unsigned keeps every reachable key away from the map's empty marker.
std::uint64_t cell_key(std::int64_t x, std::int64_t y) {
  return (static_cast<std::uint64_t>(x + (1LL << 31)) << 32) | static_cast<std::uint64_t>(y + (1LL << 31));
}

using geometry::detail::UnionFind;

}  // namespace

PatchRaster rasterise_patch(const PointList& cloud, const std::vector<std::uint32_t>& inliers,
                            const geometry::Plane& plane, double cell) {
  PatchRaster out;
  if (inliers.empty() || !(cell > 0.0)) {
    out.largest = inliers;
    return out;
  }
  Eigen::Vector3d u, v;
  geometry::plane_basis(plane.normal, u, v);
  const Point origin = cloud[inliers.front()];
  geometry::detail::CellMap cells(inliers.size());
  std::vector<std::uint32_t> cell_of(inliers.size());
  std::vector<std::pair<std::int64_t, std::int64_t>> coords;
  for (std::size_t i = 0; i < inliers.size(); ++i) {
    const Eigen::Vector3d d = cloud[inliers[i]] - origin;
    const auto cx = static_cast<std::int64_t>(std::floor(d.dot(u) / cell));
    const auto cy = static_cast<std::int64_t>(std::floor(d.dot(v) / cell));
    bool inserted = false;
    cell_of[i] = cells.find_or_insert(cell_key(cx, cy), static_cast<std::uint32_t>(coords.size()), inserted);
    if (inserted) coords.emplace_back(cx, cy);
  }
  UnionFind uf(coords.size());
  std::vector<std::uint8_t> full_neighbourhood(coords.size(), 1);
  for (std::size_t c = 0; c < coords.size(); ++c) {
    const auto [cx, cy] = coords[c];
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        if (dx == 0 && dy == 0) continue;
        const std::uint32_t other = cells.find(cell_key(cx + dx, cy + dy));
        if (other == geometry::detail::CellMap::kAbsent)
          full_neighbourhood[c] = 0;
        else
          uf.unite(static_cast<std::uint32_t>(c), other);
      }
  }
  std::vector<std::uint32_t> count(coords.size(), 0);
  for (std::uint32_t c : cell_of) ++count[uf.find(c)];
  const auto best = static_cast<std::uint32_t>(
      std::max_element(count.begin(), count.end()) - count.begin());
  for (std::size_t i = 0; i < inliers.size(); ++i) {
    if (uf.find(cell_of[i]) != best) continue;
    out.largest.push_back(inliers[i]);
    if (!full_neighbourhood[cell_of[i]]) out.border_candidates.push_back(inliers[i]);
  }
  return out;
}

PatchCurvature measure_patch_curvature(const PointList& cloud,
                                       const std::vector<std::uint32_t>& inliers,
                                       const geometry::Plane& plane) {
  PatchCurvature out;
  if (inliers.size() < 12) return out;
  Eigen::Vector3d u, v;
  geometry::plane_basis(plane.normal, u, v);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (std::uint32_t i : inliers) centroid += cloud[i];
  centroid /= static_cast<double>(inliers.size());
  // Scale in-plane coordinates to ~1 so the 6x6 normal equations stay well conditioned.
  double scale = 0.0;
  for (std::uint32_t i : inliers) scale = std::max(scale, (cloud[i] - centroid).norm());
  if (!(scale > 0.0)) return out;
  const std::size_t step = std::max<std::size_t>(1, inliers.size() / 3000);
  std::vector<Eigen::Vector3d> uvd;  // scaled u, scaled v, height above the plane
  for (std::size_t k = 0; k < inliers.size(); k += step) {
    const Eigen::Vector3d d = cloud[inliers[k]] - centroid;
    uvd.emplace_back(d.dot(u) / scale, d.dot(v) / scale, d.dot(plane.normal));
  }
  Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> atb = Eigen::Matrix<double, 6, 1>::Zero();
  auto row = [](const Eigen::Vector3d& q) {
    Eigen::Matrix<double, 6, 1> r;
    r << 1.0, q.x(), q.y(), q.x() * q.x(), q.x() * q.y(), q.y() * q.y();
    return r;
  };
  for (const auto& q : uvd) {
    const auto r = row(q);
    ata.noalias() += r * r.transpose();
    atb.noalias() += r * q.z();
  }
  const Eigen::Matrix<double, 6, 1> coef = ata.ldlt().solve(atb);
  if (!coef.allFinite()) return out;
  // The quadric's own departure from flatness: its fitted heights minus the plane that
  // best fits those heights.
  Eigen::Matrix3d pta = Eigen::Matrix3d::Zero();
  Eigen::Vector3d ptb = Eigen::Vector3d::Zero();
  std::vector<double> fitted(uvd.size());
  for (std::size_t k = 0; k < uvd.size(); ++k) {
    fitted[k] = row(uvd[k]).dot(coef);
    const Eigen::Vector3d r(1.0, uvd[k].x(), uvd[k].y());
    pta.noalias() += r * r.transpose();
    ptb.noalias() += r * fitted[k];
  }
  const Eigen::Vector3d lin = pta.ldlt().solve(ptb);
  std::vector<double> dev(uvd.size());
  for (std::size_t k = 0; k < uvd.size(); ++k)
    dev[k] = fitted[k] - Eigen::Vector3d(1.0, uvd[k].x(), uvd[k].y()).dot(lin);
  std::sort(dev.begin(), dev.end());
  const std::size_t lo = dev.size() / 50;
  out.sagitta = dev[dev.size() - 1 - lo] - dev[lo];

  // Hessian of the height in real units; its largest eigenvalue is the sharpest curvature.
  Eigen::Matrix2d hessian;
  hessian << 2.0 * coef(3), coef(4), coef(4), 2.0 * coef(5);
  hessian /= scale * scale;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(hessian);
  const int sharp = std::abs(eig.eigenvalues()(0)) > std::abs(eig.eigenvalues()(1)) ? 0 : 1;
  const double curvature = std::abs(eig.eigenvalues()(sharp));
  const Eigen::Vector2d dir = eig.eigenvectors().col(sharp);
  double lo_t = std::numeric_limits<double>::infinity(), hi_t = -lo_t;
  for (const auto& q : uvd) {
    const double t = scale * (dir.x() * q.x() + dir.y() * q.y());
    lo_t = std::min(lo_t, t);
    hi_t = std::max(hi_t, t);
  }
  if (curvature > 0.0 && hi_t > lo_t) out.radius_to_extent = (1.0 / curvature) / (hi_t - lo_t);
  return out;
}

}  // namespace cloudshape::pipeline::detail
