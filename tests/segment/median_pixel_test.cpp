// A cell's median pixel: the slot median_slot returns holds the pair nth_element puts in the
// middle, for every cell size, with tied ranges and with a NaN range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "segment/detail/median_pixel.hpp"

namespace cloudshape::segment::detail {
namespace {

std::pair<double, std::int32_t> nth_element_median(const std::vector<double>& ranges,
                                                   const std::vector<std::int32_t>& points) {
  std::vector<std::pair<double, std::int32_t>> pairs;
  for (std::size_t k = 0; k < ranges.size(); ++k) pairs.emplace_back(ranges[k], points[k]);
  std::nth_element(pairs.begin(), pairs.begin() + pairs.size() / 2, pairs.end());
  return pairs[pairs.size() / 2];
}

TEST(SegmentMedianPixel, SameAsNthElementForEveryCellSize) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> level(0, 3);  // few distinct ranges: many ties
  std::vector<std::pair<double, std::int32_t>> scratch;
  for (std::size_t n = 1; n <= 20; ++n) {
    for (int trial = 0; trial < 500; ++trial) {
      std::vector<double> ranges(n);
      std::vector<std::int32_t> points(n);
      for (std::size_t k = 0; k < n; ++k) {
        ranges[k] = 1.0 + 0.25 * level(rng);
        points[k] = static_cast<std::int32_t>(k * 7 + static_cast<std::size_t>(trial));
      }
      std::shuffle(points.begin(), points.end(), rng);
      const std::size_t slot = median_slot(ranges.data(), points.data(), n, scratch);
      ASSERT_LT(slot, n);
      const auto expected = nth_element_median(ranges, points);
      EXPECT_EQ(ranges[slot], expected.first) << n << " pixels, trial " << trial;  // exact: the same pair
      EXPECT_EQ(points[slot], expected.second) << n << " pixels, trial " << trial;
    }
  }
}

TEST(SegmentMedianPixel, ANaNRangeTakesNthElementsAnswer) {
  std::vector<std::pair<double, std::int32_t>> scratch;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<double>> cells = {
      {nan, 2.0}, {2.0, nan, 1.0}, {3.0, 1.0, nan, 2.0}, {nan, nan, 1.0, 0.5}};
  for (const auto& ranges : cells) {
    std::vector<std::int32_t> points(ranges.size());
    for (std::size_t k = 0; k < points.size(); ++k) points[k] = static_cast<std::int32_t>(10 + k);
    const std::size_t slot = median_slot(ranges.data(), points.data(), ranges.size(), scratch);
    ASSERT_LT(slot, ranges.size());
    EXPECT_EQ(points[slot], nth_element_median(ranges, points).second) << ranges.size() << " pixels";
  }
}

}  // namespace
}  // namespace cloudshape::segment::detail
