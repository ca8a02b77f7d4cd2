// Covariance of a point set and its eigen-decomposition (thesis 3.2.1): the
// centroid, eigenvalues ascending (lambda0 <= lambda1 <= lambda2) and eigenvectors.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::geometry {

struct Pca {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();   // ascending
  Eigen::Matrix3d eigenvectors = Eigen::Matrix3d::Identity();  // column i <-> eigenvalues[i]

  // Surface variation lambda0 / (lambda0 + lambda1 + lambda2) (thesis eq. 3.5): 0 for a
  // plane, 1/3 for isotropic points.
  double surface_variation() const;
};

Pca compute_pca(const PointList& points);
Pca compute_pca(const PointList& points, const std::vector<std::uint32_t>& indices);

}  // namespace cloudshape::geometry
