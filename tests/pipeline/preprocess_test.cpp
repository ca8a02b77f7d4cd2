// Stage 1: the point budget, the resolution, the outlier filter and the smoothing.
#include <gtest/gtest.h>

#include "stage_fixtures.hpp"

namespace cloudshape::pipeline {
namespace {

TEST(Preprocess, DenseCloudIsBroughtUnderThePointBudget) {
  config::PreprocessConfig cfg;
  std::mt19937_64 rng(1);
  const auto spec = synth::make_solid(synth::ShapeKind::box, {3, 2, 1});
  const PointList raw = synth::sample_solid_surface(spec, 200000, rng);
  const PreprocessedCloud pre = preprocess_cloud(raw, cfg);
  EXPECT_LE(pre.points.size(), static_cast<std::size_t>(cfg.max_points) * 6 / 5);
  EXPECT_GT(pre.points.size(), static_cast<std::size_t>(cfg.max_points) / 3);
  // On a surface sampled at one point per voxel, the spacing is about the voxel edge.
  EXPECT_GT(pre.resolution, 0.3 * pre.voxel_size);
  EXPECT_LT(pre.resolution, 1.5 * pre.voxel_size);
}

TEST(Preprocess, StrayPointsAreRemoved) {
  config::PreprocessConfig cfg;
  std::mt19937_64 rng(2);
  const auto spec = synth::make_solid(synth::ShapeKind::sphere, {1.0});
  PointList raw = synth::sample_solid_surface(spec, 20000, rng);
  raw.emplace_back(0.0, 0.0, 0.0);  // centre of the sphere: nowhere near the surface
  raw.emplace_back(1.6, 1.6, 1.6);
  const PreprocessedCloud pre = preprocess_cloud(raw, cfg);
  EXPECT_GE(pre.outliers_removed, 2u);
  for (const Point& p : pre.points) EXPECT_GT(p.norm(), 0.9);
}

TEST(Preprocess, StatisticalFilterDropsFarPoints) {
  PointList pts;
  for (int x = 0; x < 30; ++x)
    for (int y = 0; y < 30; ++y) pts.emplace_back(0.1 * x, 0.1 * y, 0.0);
  pts.emplace_back(1.5, 1.5, 3.0);
  std::size_t removed = 0;
  const PointList kept = remove_statistical_outliers(pts, 8, 3.0, &removed);
  EXPECT_EQ(removed, 1u);
  EXPECT_EQ(kept.size(), 900u);
}

TEST(Preprocess, SmoothingFlattensNoisyFacesButKeepsTheCorner) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.002);
  PointList pts;
  for (int x = 0; x < 40; ++x)
    for (int y = 0; y < 40; ++y) pts.emplace_back(0.02 * x, 0.02 * y, noise(rng));
  const PointList smoothed = smooth_flat_regions(pts, 16, 0.05);
  double before = 0, after = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    before += pts[i].z() * pts[i].z();
    after += smoothed[i].z() * smoothed[i].z();
  }
  EXPECT_LT(after, 0.5 * before);
  // A sharp corner is not flat: it is left where it is.
  PointList corner;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      corner.emplace_back(0.0, -0.1 * i, -0.1 * j);
      corner.emplace_back(-0.1 * i, 0.0, -0.1 * j);
      corner.emplace_back(-0.1 * i, -0.1 * j, 0.0);
    }
  const PointList kept = smooth_flat_regions(corner, 16, 0.01);
  EXPECT_LT((kept[0] - corner[0]).norm(), 1e-12);
}

TEST(Preprocess, EmptyCloudGivesEmptyResult) {
  const PreprocessedCloud pre = preprocess_cloud({}, config::PreprocessConfig{});
  EXPECT_TRUE(pre.points.empty());
  EXPECT_EQ(pre.resolution, 0.0);
}

}  // namespace
}  // namespace cloudshape::pipeline
