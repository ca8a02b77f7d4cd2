// Positive cylinder recognition against ground truth: noisy, with outliers, seen from one side.
// Radius, height, centre (mid-axis) and the axis (sign free) within stated tolerances.
#include <gtest/gtest.h>

#include "positive_support.hpp"

namespace cloudshape::positive {
namespace {

const std::vector<std::uint64_t> kSeeds = {21, 22, 23, 24};

synth::SolidSpec random_cylinder(std::mt19937_64& rng) {
  const double height = random_size(rng);
  const double radius = height * std::uniform_real_distribution<double>(0.15, 0.45)(rng);
  return synth::make_solid(synth::ShapeKind::cylinder, {radius, height}, random_pose(rng, height));
}

// Measured (see the "[measured]" lines): ...
constexpr Tolerance kNoisy{0.02, 0.01, 1.0};
constexpr Tolerance kOutliers{0.03, 0.01, 1.0};
constexpr Tolerance kSingleView{0.02, 0.01, 1.0};

TEST(CylinderParameters, Noisy) {
  check_seeds(kSeeds, random_cylinder, [](const auto&, auto&) { return noisy(); }, false, kNoisy);
}

TEST(CylinderParameters, NoisyWithOutliers) {
  check_seeds(kSeeds, random_cylinder, [](const auto&, auto&) { return noisy_with_outliers(); }, false, kOutliers);
}

// 40-65 deg off the axis: one cap and the near half of the side, seen from rim to rim, so
// the radius, the height and the centre are all determined by the view.
TEST(CylinderParameters, SingleViewOfACapAndTheSide) {
  check_seeds(
      kSeeds, random_cylinder,
      [](const synth::SolidSpec& truth, std::mt19937_64& rng) {
        const double off_axis = std::uniform_real_distribution<double>(40.0, 65.0)(rng);
        return seen_from(from_axis(truth, std::bernoulli_distribution(0.5)(rng) ? off_axis : 180.0 - off_axis, rng));
      },
      true, kSingleView);
}

// Square to the axis: half the side and no cap; the arc still gives the radius, and the
// side's extent the height.
TEST(CylinderParameters, SingleViewOfTheSideOnly) {
  check_seeds(
      kSeeds, random_cylinder,
      [](const synth::SolidSpec& truth, std::mt19937_64& rng) { return seen_from(from_axis(truth, 90.0, rng)); },
      true, kSingleView);
}

}  // namespace
}  // namespace cloudshape::positive
