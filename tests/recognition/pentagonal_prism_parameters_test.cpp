// Positive pentagonal prism recognition against ground truth: noisy, with outliers, one view.
// Side, height, centre, the axis (sign free) and the pentagon's turn about it within tolerances.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace cloudshape::positive
