// Positive cylinder recognition against ground truth: noisy, with outliers, seen from one side.
// Radius, height, centre (mid-axis) and the axis (sign free) within stated tolerances.
#include <gtest/gtest.h>

#include "positive_support.hpp"

namespace cloudshape::positive {
namespace {

const std::vector<std::uint64_t> kSeeds = {21, 22, 23, 24, 25, 26};

synth::SolidSpec cylinder(std::mt19937_64& rng, double least_ratio, double most_ratio) {
  const double height = random_size(rng);
  const double radius =
      height * std::uniform_real_distribution<double>(least_ratio, most_ratio)(rng);
  return synth::make_solid(synth::ShapeKind::cylinder, {radius, height}, random_pose(rng, height));
}

// Radius 0.25-0.5 of the height: slimmer ones fail often today (the DISABLED_ tests below).
synth::SolidSpec random_cylinder(std::mt19937_64& rng) { return cylinder(rng, 0.25, 0.5); }
synth::SolidSpec slim_cylinder(std::mt19937_64& rng) { return cylinder(rng, 0.15, 0.25); }

// Worst over 46 seeds (40 others and these 6) when these were set, the bug's seeds aside (dimension
// / centre share of size / axis): noise 0.23% / 0.08% / 0.23 deg, outliers 0.14% / 0.05% / 0.27
// deg, single views 0.80% / 0.31% / 0.07 deg, noisy single view 0.87% / 0.37% / 0.46 deg. Each
// tolerance is 2-4 times that; a 5% radius error fails.
constexpr Tolerance kNoisy{0.01, 0.005, 1.0};
constexpr Tolerance kOutliers{0.01, 0.005, 1.0};
constexpr Tolerance kSingleView{0.015, 0.01, 0.5};
constexpr Tolerance kSingleViewNoisy{0.02, 0.01, 1.0};

Condition oblique_view(const synth::SolidSpec& truth, std::mt19937_64& rng, double noise = 0.0) {
  const double off_axis = std::uniform_real_distribution<double>(40.0, 65.0)(rng);
  return seen_from(
      from_axis(truth, std::bernoulli_distribution(0.5)(rng) ? off_axis : 180.0 - off_axis, rng),
      noise);
}

Condition side_view(const synth::SolidSpec& truth, std::mt19937_64& rng) {
  return seen_from(from_axis(truth, 90.0, rng));
}

TEST(CylinderParameters, Noisy) {
  check_seeds(
      kSeeds, random_cylinder, [](const auto&, auto&) { return noisy(); }, false, kNoisy);
}

TEST(CylinderParameters, NoisyWithOutliers) {
  check_seeds(
      kSeeds, random_cylinder, [](const auto&, auto&) { return noisy_with_outliers(); }, false,
      kOutliers);
}

// 40-65 deg off the axis: one cap and the near half of the side, seen from rim to rim, so
// the radius, the height and the centre are all determined by the view.
TEST(CylinderParameters, SingleViewOfACapAndTheSide) {
  check_seeds(
      kSeeds, random_cylinder, [](const auto& t, auto& rng) { return oblique_view(t, rng); }, true,
      kSingleView);
}

TEST(CylinderParameters, SingleViewOfACapAndTheSideNoisy) {
  check_seeds(
      kSeeds, random_cylinder, [](const auto& t, auto& rng) { return oblique_view(t, rng, 0.005); },
      true, kSingleViewNoisy);
}

// Square to the axis: half the side and no cap; the arc still gives the radius, and the
// side's extent the height.
TEST(CylinderParameters, SingleViewOfTheSideOnly) {
  check_seeds(kSeeds, random_cylinder, side_view, true, kSingleView);
}

TEST(CylinderParameters, SlimSingleViewOfACapAndTheSide) {
  check_seeds(
      kSeeds, slim_cylinder, [](const auto& t, auto& rng) { return oblique_view(t, rng); }, true,
      kSingleView);
}

// Recognizer bug (reported on issue 16): under noise of 0.5% of the height, some cylinders
// come out with the radius 3-7% short, the height up to 2.6% long and the axis up to 2.4 deg
// off, where the others are within 0.25%: 19 of 40 slim ones (radius 0.15-0.25 of the
// height; the first four below) and 1 of 40 in the enabled range (the last). In these the
// plane segmentation finds side strips only, no cap, so fit_cylinder takes the axis from
// every normal and fits the circle to every point, the cap discs' too.
TEST(CylinderParameters, DISABLED_NoisyRadiusUpToSevenPercentShort) {
  const auto noise = [](const auto&, auto&) { return noisy(); };
  check_seeds({21002002, 21002003, 21002005, 21002009}, slim_cylinder, noise, false, kNoisy);
  check_seeds({21025}, random_cylinder, noise, false, kNoisy);
}

// Recognizer bug (reported on issue 16): a clean view square to the axis, 10k points, is
// recognised as a box for 9 of 40 slim cylinders (the first four below) and 2 of 40 in the
// enabled range (the last two). The tangent strips along the two silhouettes pass for faces
// facing opposite ways, fit_cylinder takes them for the caps (an axis square to the true
// one), the cylinder fails verification and a box wins (confidence 0.43).
TEST(CylinderParameters, DISABLED_SideViewTakenForABox) {
  check_seeds({21008006, 21008013, 21008019, 21008022}, slim_cylinder, side_view, true,
              kSingleView);
  check_seeds({21028, 21039}, random_cylinder, side_view, true, kSingleView);
}

}  // namespace
}  // namespace cloudshape::positive
