// Positive pentagonal prism recognition against ground truth: noisy, with outliers, one view.
// Side, height, centre, the axis (sign free) and the pentagon's turn about it within tolerances.
#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <string>

#include "positive_support.hpp"
#include "synth/solid_geometry.hpp"

namespace cloudshape::positive {
namespace {

const std::vector<std::uint64_t> kSeeds = {51, 52, 53, 54, 55, 56};

synth::SolidSpec random_prism(std::mt19937_64& rng) {
  const double side = random_size(rng);
  const double height = side * std::uniform_real_distribution<double>(0.8, 3.0)(rng);
  return synth::make_solid(synth::ShapeKind::pentagonal_prism, {side, height},
                           random_pose(rng, height));
}

// Outward normal of the side between pentagon vertices k and k+1, in world coordinates.
Eigen::Vector3d side_normal(const synth::SolidSpec& truth, int k) {
  const auto v = synth::pentagon_vertices(1.0);
  return truth.pose.axes.transpose() * (v[k] + v[(k + 1) % 5]).normalized();
}

// Worst over 46 seeds (40 others and these 6) when these were set (dimension / centre share of size
// / axes): noise 0.41% / 0.10% / 0.31 deg, outliers 0.27% / 0.08% / 0.17 deg, single views 0.95% /
// 0.32% / 0.03 deg, noisy single view 1.0% / 0.34% / 0.69 deg. Each tolerance is 2-3 times that.
constexpr Tolerance kNoisy{0.01, 0.005, 1.0};
constexpr Tolerance kOutliers{0.01, 0.005, 1.0};
constexpr Tolerance kSingleView{0.02, 0.01, 0.5};
constexpr Tolerance kSingleViewNoisy{0.02, 0.01, 1.5};

TEST(PentagonalPrismParameters, Noisy) {
  check_seeds(
      kSeeds, random_prism, [](const auto&, auto&) { return noisy(); }, false, kNoisy);
}

TEST(PentagonalPrismParameters, NoisyWithOutliers) {
  check_seeds(
      kSeeds, random_prism, [](const auto&, auto&) { return noisy_with_outliers(); }, false,
      kOutliers);
}

// Square to two neighbouring sides: those two alone, both whole.
TEST(PentagonalPrismParameters, SingleViewOfTwoSides) {
  check_seeds(
      kSeeds, random_prism,
      [](const synth::SolidSpec& truth, auto&) {
        return seen_from(side_normal(truth, 0) + side_normal(truth, 1));
      },
      true, kSingleView);
}

// Square to a side and up the axis: three sides and a cap.
TEST(PentagonalPrismParameters, SingleViewOfThreeSidesAndACap) {
  check_seeds(
      kSeeds, random_prism,
      [](const synth::SolidSpec& truth, auto&) {
        return seen_from(side_normal(truth, 2) + 0.6 * truth.pose.axes.row(0).transpose());
      },
      true, kSingleView);
}

TEST(PentagonalPrismParameters, SingleViewOfThreeSidesAndACapNoisy) {
  check_seeds(
      kSeeds, random_prism,
      [](const synth::SolidSpec& truth, auto&) {
        return seen_from(side_normal(truth, 2) + 0.6 * truth.pose.axes.row(0).transpose(), 0.005);
      },
      true, kSingleViewNoisy);
}

// The accuracy's outliers condition at its largest clouds: 200 000 points, noise sigma 1% of size
// and 3% outliers, a flat prism (side 58.78, height 43.14, as its cloud 19). A side's plane then
// holds its neighbours' noisy points near each edge and outliers across it, and spans up to 19%
// more than the side: while every seen side had to be no wider than the side and its neighbours'
// bands, five of these eight were named cylinders or unknown. That test is made only where a side's
// end placed a hidden neighbour (between seen sides their positions fix the pentagon): measured,
// all eight pentagonal prisms, side within 1.1%, height within 3.1% (the caps' planes in that
// noise), axis within 1.6 deg (tolerances 5% and 3 deg).
TEST(PentagonalPrismParameters, WholeUnderNoiseAndOutliersSidesMaySpanMore) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    std::mt19937_64 rng(seed);
    const synth::SolidSpec truth = synth::make_solid(synth::ShapeKind::pentagonal_prism,
                                                     {58.78, 43.14}, random_pose(rng, 58.78));
    const Condition condition{"noise 1% and 3% outliers", 200000, 0.01, 0.03, std::nullopt};
    expect_recognised(make_cloud(truth, condition, seed), truth, false, {0.05, 0.01, 3.0},
                      "seed " + std::to_string(seed));
  }
}

}  // namespace
}  // namespace cloudshape::positive
