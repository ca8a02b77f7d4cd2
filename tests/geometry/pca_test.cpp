// Covariance eigen-analysis and the surface variation that types key-points (thesis 3.2).
#include <gtest/gtest.h>

#include <random>

#include "geometry/pca.hpp"

namespace cloudshape::geometry {
namespace {

TEST(Pca, FlatPatchHasZeroSurfaceVariationAndItsNormal) {
  PointList pts;
  const Eigen::Vector3d n = Eigen::Vector3d(0, 1, 1).normalized();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) pts.push_back(Point(1, 2, 3) + 0.1 * i * u + 0.1 * j * v);
  const Pca pca = compute_pca(pts);
  EXPECT_LT(pca.surface_variation(), 1e-12);
  EXPECT_NEAR(std::abs(pca.eigenvectors.col(0).dot(n)), 1.0, 1e-9);
  EXPECT_LT((pca.centroid - Point(1, 2, 3)).norm(), 1e-12);
}

TEST(Pca, CubeCornerIsFarFromFlat) {
  // Three faces meeting at the origin: the neighbourhood of a box corner.
  PointList pts;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      pts.emplace_back(0.0, -0.1 * i, -0.1 * j);
      pts.emplace_back(-0.1 * i, 0.0, -0.1 * j);
      pts.emplace_back(-0.1 * i, -0.1 * j, 0.0);
    }
  const Pca pca = compute_pca(pts);
  EXPECT_GT(pca.surface_variation(), 0.1);
  // By symmetry the (1,1,1) diagonal is an eigenvector.
  const Eigen::Vector3d diag = Eigen::Vector3d::Ones().normalized();
  double best = 0;
  for (int k = 0; k < 3; ++k) best = std::max(best, std::abs(pca.eigenvectors.col(k).dot(diag)));
  EXPECT_NEAR(best, 1.0, 1e-9);
}

TEST(Pca, IsotropicPointsApproachOneThird) {
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g;
  PointList pts;
  for (int i = 0; i < 20000; ++i) pts.emplace_back(g(rng), g(rng), g(rng));
  EXPECT_NEAR(compute_pca(pts).surface_variation(), 1.0 / 3.0, 0.01);
}

TEST(Pca, EigenvaluesAscendAndMatchTheVariances) {
  PointList pts;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) pts.emplace_back(3.0 * sx, 2.0 * sy, 1.0 * sz);
  const Pca pca = compute_pca(pts);
  EXPECT_NEAR(pca.eigenvalues[0], 1.0, 1e-12);
  EXPECT_NEAR(pca.eigenvalues[1], 4.0, 1e-12);
  EXPECT_NEAR(pca.eigenvalues[2], 9.0, 1e-12);
}

}  // namespace
}  // namespace cloudshape::geometry
