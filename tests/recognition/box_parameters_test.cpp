// Positive box recognition against ground truth: noisy, with outliers, seen from one side.
// Length, width, height, centre and all three axes (sign free) within stated tolerances.
#include <gtest/gtest.h>

#include "positive_support.hpp"

namespace cloudshape::positive {
namespace {

const std::vector<std::uint64_t> kSeeds = {11, 12, 13, 14, 15, 16};

// Edges at least 20% apart, so every axis is defined (a near-cube's are not).
synth::SolidSpec random_box(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double length = random_size(rng);
  const double width = length * (0.5 + 0.3 * u(rng));
  const double height = width * (0.35 + 0.45 * u(rng));
  return synth::make_solid(synth::ShapeKind::box, {length, width, height},
                           random_pose(rng, length));
}

// Worst over 46 seeds (40 others and these 6) when these were set (dimension / centre share of size
// / axes): noise 0.45% / 0.08% / 0.42 deg, outliers 0.73% / 0.10% / 0.26 deg, single view 0.96% /
// 0.41% / 0.02 deg, noisy single view 3.1% / 0.33% / 0.80 deg. Each tolerance is 2-3 times that
// (1.6 for the noisy view's dimensions); a 10% error fails. The noisy view's 3.1% is a height of
// 0.18 of the length: a hidden face sits where the points end, within about one point spacing (0.7%
// of the length), whatever the edge.
constexpr Tolerance kNoisy{0.01, 0.005, 1.0};
constexpr Tolerance kOutliers{0.02, 0.005, 1.0};
constexpr Tolerance kSingleView{0.02, 0.01, 0.5};
constexpr Tolerance kSingleViewNoisy{0.05, 0.01, 2.0};

TEST(BoxParameters, Noisy) {
  check_seeds(
      kSeeds, random_box, [](const auto&, auto&) { return noisy(); }, false, kNoisy);
}

TEST(BoxParameters, NoisyWithOutliers) {
  check_seeds(
      kSeeds, random_box, [](const auto&, auto&) { return noisy_with_outliers(); }, false,
      kOutliers);
}

// The camera in the octant of one corner sees the three faces that meet there, every edge
// whole: all three dimensions and the centre are determined by the view.
Eigen::Vector3d towards_a_corner(const synth::SolidSpec& truth, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> share(0.4, 1.0);
  std::bernoulli_distribution flip(0.5);
  Eigen::Vector3d local;
  for (int k = 0; k < 3; ++k) local[k] = (flip(rng) ? -1.0 : 1.0) * share(rng);
  return truth.pose.axes.transpose() * local;
}

TEST(BoxParameters, SingleViewOfThreeFaces) {
  check_seeds(
      kSeeds, random_box,
      [](const auto& truth, auto& rng) { return seen_from(towards_a_corner(truth, rng)); }, true,
      kSingleView);
}

TEST(BoxParameters, SingleViewOfThreeFacesNoisy) {
  check_seeds(
      kSeeds, random_box,
      [](const auto& truth, auto& rng) { return seen_from(towards_a_corner(truth, rng), 0.005); },
      true, kSingleViewNoisy);
}

}  // namespace
}  // namespace cloudshape::positive
