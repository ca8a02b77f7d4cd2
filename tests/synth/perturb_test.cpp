// Noise has the requested sigma; outliers have the requested count and stay near the cloud.
#include "synth/perturb.hpp"
#include "synth/sample_solid.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

TEST(GaussianNoise, PerCoordinateSigmaMatches) {
  std::mt19937_64 rng(21);
  PointList points(100000, Point(1.0, -2.0, 3.0));
  add_gaussian_noise(points, 0.25, rng);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), square = Eigen::Vector3d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector3d d = p - Point(1.0, -2.0, 3.0);
    mean += d;
    square += d.cwiseProduct(d);
  }
  mean /= points.size();
  square /= points.size();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(mean[k], 0.0, 0.005);
    EXPECT_NEAR(std::sqrt(square[k]), 0.25, 0.25 * 0.01);
  }
}

TEST(GaussianNoise, SigmaAlongTheSurfaceNormalMatches) {
  std::mt19937_64 rng(22);
  PointList points = sample_solid_surface(make_solid(ShapeKind::sphere, {10.0}), 100000, rng);
  add_gaussian_noise(points, 0.05, rng);
  double square = 0.0;
  for (const auto& p : points) square += (p.norm() - 10.0) * (p.norm() - 10.0);
  EXPECT_NEAR(std::sqrt(square / points.size()), 0.05, 0.05 * 0.01);
}

TEST(GaussianNoise, ZeroSigmaIsIdentityAndNegativeThrows) {
  std::mt19937_64 rng(23);
  PointList points{{1, 2, 3}};
  add_gaussian_noise(points, 0.0, rng);
  EXPECT_EQ(points[0], Point(1, 2, 3));
  EXPECT_THROW(add_gaussian_noise(points, -1.0, rng), std::invalid_argument);
}

TEST(Outliers, CountAndRegion) {
  std::mt19937_64 rng(24);
  PointList points = sample_solid_surface(make_solid(ShapeKind::box, {10.0, 4.0, 2.0}), 10000, rng);
  add_outliers(points, 0.1, rng);
  ASSERT_EQ(points.size(), 11000u);
  std::size_t outside = 0;
  for (std::size_t i = 10000; i < points.size(); ++i) {
    const auto& p = points[i];
    EXPECT_LE(std::abs(p.x()), 5.5 + 1e-12);
    EXPECT_LE(std::abs(p.y()), 2.2 + 1e-12);
    EXPECT_LE(std::abs(p.z()), 1.1 + 1e-12);
    if (std::abs(p.x()) > 5 || std::abs(p.y()) > 2 || std::abs(p.z()) > 1) ++outside;
  }
  // The margin shell is 1 - 1/1.1^3 = 25% of the grown box's volume.
  EXPECT_NEAR(outside / 1000.0, 1.0 - 1.0 / (1.1 * 1.1 * 1.1), 0.05);
}

TEST(Outliers, EmptyCloudAndRounding) {
  std::mt19937_64 rng(25);
  PointList empty;
  add_outliers(empty, 0.5, rng);
  EXPECT_TRUE(empty.empty());
  PointList flat(7, Point(0, 0, 0));
  flat[1] = Point(1, 0, 0);
  add_outliers(flat, 0.3, rng);  // round(2.1) = 2
  EXPECT_EQ(flat.size(), 9u);
  EXPECT_THROW(add_outliers(flat, -0.1, rng), std::invalid_argument);
}

}  // namespace
}  // namespace cloudshape::synth
