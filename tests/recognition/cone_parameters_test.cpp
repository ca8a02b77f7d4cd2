// Positive cone recognition against ground truth: noisy, with outliers, seen from one side.
// Radius, height, centre (of the base) and the signed axis (base to apex) within tolerances.
#include <gtest/gtest.h>

#include "positive_support.hpp"

namespace cloudshape::positive {
namespace {

const std::vector<std::uint64_t> kSeeds = {31, 32, 33, 34, 35, 36};

synth::SolidSpec random_cone(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double size = random_size(rng);
  const double height = size * (0.6 + 0.4 * u(rng));
  const double radius = size * (0.25 + 0.25 * u(rng));
  return synth::make_solid(synth::ShapeKind::cone, {radius, height}, random_pose(rng, size));
}

// Worst over 46 seeds (40 others and these 6) when these were set (dimension / centre share of size
// / axis): noise 0.35% / 0.39% / 1.07 deg, outliers 0.37% / 0.77% / 1.36 deg, single views 0.43% /
// 0.19% / 0.09 deg, noisy view of the base and side 2.3% (the height: the apex is extrapolated from
// the side) / 0.38% / 0.77 deg. Each tolerance is 2-3 times that.
constexpr Tolerance kNoisy{0.01, 0.01, 2.5};
constexpr Tolerance kOutliers{0.01, 0.02, 3.0};
constexpr Tolerance kSingleView{0.01, 0.005, 0.5};
constexpr Tolerance kSingleViewNoisy{0.05, 0.01, 2.0};

TEST(ConeParameters, Noisy) {
  check_seeds(
      kSeeds, random_cone, [](const auto&, auto&) { return noisy(); }, false, kNoisy);
}

TEST(ConeParameters, NoisyWithOutliers) {
  check_seeds(
      kSeeds, random_cone, [](const auto&, auto&) { return noisy_with_outliers(); }, false,
      kOutliers);
}

// From below the base, 120-135 deg from the axis: the base disc and part of the side.
TEST(ConeParameters, SingleViewOfTheBaseAndTheSide) {
  check_seeds(
      kSeeds, random_cone,
      [](const synth::SolidSpec& truth, std::mt19937_64& rng) {
        return seen_from(
            from_axis(truth, std::uniform_real_distribution<double>(120.0, 135.0)(rng), rng));
      },
      true, kSingleView);
}

TEST(ConeParameters, SingleViewOfTheBaseAndTheSideNoisy) {
  check_seeds(
      kSeeds, random_cone,
      [](const synth::SolidSpec& truth, std::mt19937_64& rng) {
        return seen_from(
            from_axis(truth, std::uniform_real_distribution<double>(120.0, 135.0)(rng), rng),
            0.005);
      },
      true, kSingleViewNoisy);
}

// From the apex side, 50-80 deg from the axis: the side only, from the apex down to the
// rim on the camera's side, which fixes the radius and the height.
TEST(ConeParameters, SingleViewOfTheSideOnly) {
  check_seeds(
      kSeeds, random_cone,
      [](const synth::SolidSpec& truth, std::mt19937_64& rng) {
        return seen_from(
            from_axis(truth, std::uniform_real_distribution<double>(50.0, 80.0)(rng), rng));
      },
      true, kSingleView);
}

}  // namespace
}  // namespace cloudshape::positive
