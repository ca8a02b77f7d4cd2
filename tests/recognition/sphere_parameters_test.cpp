// Positive sphere recognition against ground truth: noisy, with outliers, seen from one side.
// Radius and centre within stated tolerances (a sphere's axes are any orthonormal set).
#include <gtest/gtest.h>

#include "positive_support.hpp"

namespace cloudshape::positive {
namespace {

const std::vector<std::uint64_t> kSeeds = {41, 42, 43, 44, 45, 46};

synth::SolidSpec random_sphere(std::mt19937_64& rng) {
  const double radius = random_size(rng);
  return synth::make_solid(synth::ShapeKind::sphere, {radius}, random_pose(rng, 2.0 * radius));
}

// Worst over 46 seeds (40 others and these 6) when these were set (radius / centre share of the
// diameter): noise 0.03% / 0.03%, outliers 0.08% / 0.09%, single view 0.00% / 0.00%, noisy single
// view 0.12% / 0.12%. One tolerance, 4 times the worst.
constexpr Tolerance kNoisy{0.005, 0.005, 0.0};
constexpr Tolerance kOutliers{0.005, 0.005, 0.0};
constexpr Tolerance kSingleView{0.005, 0.005, 0.0};

TEST(SphereParameters, Noisy) {
  check_seeds(
      kSeeds, random_sphere, [](const auto&, auto&) { return noisy(); }, false, kNoisy);
}

TEST(SphereParameters, NoisyWithOutliers) {
  check_seeds(
      kSeeds, random_sphere, [](const auto&, auto&) { return noisy_with_outliers(); }, false,
      kOutliers);
}

// A hemisphere at most: the radius and the centre are still determined.
TEST(SphereParameters, SingleView) {
  check_seeds(
      kSeeds, random_sphere,
      [](const synth::SolidSpec& truth, std::mt19937_64& rng) {
        return seen_from(
            from_axis(truth, std::uniform_real_distribution<double>(0.0, 180.0)(rng), rng));
      },
      true, kSingleView);
}

TEST(SphereParameters, SingleViewNoisy) {
  check_seeds(
      kSeeds, random_sphere,
      [](const synth::SolidSpec& truth, std::mt19937_64& rng) {
        return seen_from(
            from_axis(truth, std::uniform_real_distribution<double>(0.0, 180.0)(rng), rng), 0.005);
      },
      true, kSingleView);
}

}  // namespace
}  // namespace cloudshape::positive
