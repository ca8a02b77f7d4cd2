#include "geometry/pca.hpp"

#include <Eigen/Eigenvalues>

namespace cloudshape::geometry {
namespace {

template <class Get>
Pca pca_of(std::size_t n, Get get) {
  Pca out;
  if (n == 0) return out;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) mean += get(i);
  mean /= static_cast<double>(n);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = get(i) - mean;
    cov.noalias() += d * d.transpose();
  }
  cov /= static_cast<double>(n);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  out.centroid = mean;
  out.eigenvalues = solver.eigenvalues().cwiseMax(0.0);
  out.eigenvectors = solver.eigenvectors();
  return out;
}

}  // namespace

double Pca::surface_variation() const {
  const double sum = eigenvalues.sum();
  return sum > 0.0 ? eigenvalues[0] / sum : 0.0;
}

Pca compute_pca(const PointList& points) {
  return pca_of(points.size(), [&](std::size_t i) -> const Point& { return points[i]; });
}

Pca compute_pca(const PointList& points, const std::vector<std::uint32_t>& indices) {
  return pca_of(indices.size(), [&](std::size_t i) -> const Point& { return points[indices[i]]; });
}

}  // namespace cloudshape::geometry
