// Stage 1: the point budget, the resolution, the outlier filter and the smoothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/voxel_grid.hpp"
#include "parallel/thread_pool.hpp"
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

// The voxel the size search ends at, its grid and how often the whole cloud's grid was too
// large, as gridding the whole cloud at every step gives them (the loop preprocessing ran before
// it counted a dense cloud's grids instead).
struct Gridded {
  double voxel = 0.0;
  PointList points;
  int coarsened = 0;
};

Gridded gridded_each_time(const PointList& raw, const config::PreprocessConfig& cfg) {
  const geometry::Bounds bounds = geometry::bounding_box(raw);
  double voxel = bounds.diagonal() / cfg.voxel_divisions;
  const auto budget = static_cast<std::size_t>(cfg.max_points);
  const auto coarser = [&](std::size_t n) {
    return voxel * std::sqrt(static_cast<double>(n) / static_cast<double>(budget)) * 1.02;
  };
  const std::size_t stride = std::max<std::size_t>(1, raw.size() / (budget * 4));
  const geometry::Bounds sparse = geometry::bounding_box(raw, stride);
  for (int attempt = 0; attempt < 4; ++attempt) {
    const std::size_t n = geometry::count_occupied_voxels(raw, voxel, &sparse, stride);
    if (n <= budget) break;
    voxel = coarser(n);
  }
  const int neighbours = static_cast<int>(cfg.isolated_voxel_neighbours);
  Gridded out;
  out.points = geometry::voxel_grid_downsample(raw, voxel, neighbours, nullptr, &bounds);
  for (; out.coarsened < 3 && out.points.size() > budget + budget / 5; ++out.coarsened) {
    voxel = coarser(out.points.size());
    out.points = geometry::voxel_grid_downsample(raw, voxel, neighbours, nullptr, &bounds);
  }
  out.voxel = voxel;
  return out;
}

// Half a million points for 3 000, searched first on one point in 41: a scanned grid of 41 x 24
// columns, so that the subsample lies on 24 columns alone and occupies far too few voxels, and
// the whole cloud's grid is coarsened after. The grid sizes counted, the cloud gridded once: the
// same voxel and points, with and without a pool, as gridding every time.
TEST(Preprocess, ADenseCloudsCountedGridsAreTheGridsItWouldHaveBuilt) {
  config::PreprocessConfig cfg;
  cfg.max_points = 3000;
  PointList raw;
  for (int row = 0; row < 508; ++row) {
    for (int column = 0; column < 41 * 24; ++column)
      raw.emplace_back(0.01 * column, 0.01 * row,
                       0.1 * std::sin(0.02 * column) * std::cos(0.03 * row));
  }
  ASSERT_EQ(raw.size() / (4 * static_cast<std::size_t>(cfg.max_points)), 41u);
  const Gridded reference = gridded_each_time(raw, cfg);
  EXPECT_GE(reference.coarsened, 1);
  parallel::ThreadPool two(2);
  for (parallel::ThreadPool* pool : {static_cast<parallel::ThreadPool*>(nullptr), &two}) {
    const PreprocessedCloud pre = preprocess_cloud(raw, cfg, pool);
    EXPECT_EQ(pre.voxel_size, reference.voxel);
    EXPECT_EQ(pre.points, reference.points);
  }
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
