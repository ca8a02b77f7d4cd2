// The pixel an organized graph's cell keeps as its node: the one of median range, picked as
// nth_element picks it from (range, point) pairs, without building the pairs for a small cell.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cloudshape::segment::detail {

// Cells of up to this many pixels rank them by comparisons instead of selecting.
constexpr std::size_t kRankedCellPixels = 8;

// The slot k < n whose (ranges[k], points[k]) nth_element puts at n / 2 of those pairs in
// std::pair's order. The points are distinct, so without a NaN range that order is strict and
// total and the pair of rank n / 2 is the one whatever the steps: up to four pixels (a cell of
// stride 2) compare as a network does, up to kRankedCellPixels count each one's rank. A NaN
// range (no strict order: the answer is nth_element's) or a large cell goes through nth_element
// on `scratch`. n > 0.
inline std::size_t median_slot(const double* ranges, const std::int32_t* points, std::size_t n,
                               std::vector<std::pair<double, std::int32_t>>& scratch) {
  bool ordered = n <= kRankedCellPixels;
  for (std::size_t k = 0; k < n && ordered; ++k) ordered = ranges[k] == ranges[k];
  const auto before = [&](std::size_t j, std::size_t k) {
    return ranges[j] < ranges[k] || (ranges[j] == ranges[k] && points[j] < points[k]);
  };
  if (ordered && n <= 4) {
    if (n == 1) return 0;
    if (n == 2) return before(0, 1) ? 1 : 0;
    if (n == 3) {
      if (before(0, 1)) return before(1, 2) ? 1 : before(0, 2) ? 2 : 0;
      return before(0, 2) ? 0 : before(1, 2) ? 2 : 1;
    }
    // Rank 2 of 4: the larger of the smaller one of the pairs' larger ends and the larger one of
    // their smaller ends.
    const bool first_up = before(0, 1), second_up = before(2, 3);
    const std::size_t low1 = first_up ? 0 : 1, high1 = first_up ? 1 : 0;
    const std::size_t low2 = second_up ? 2 : 3, high2 = second_up ? 3 : 2;
    const std::size_t lower_high = before(high1, high2) ? high1 : high2;
    const std::size_t higher_low = before(low1, low2) ? low2 : low1;
    return before(lower_high, higher_low) ? higher_low : lower_high;
  }
  if (ordered) {
    for (std::size_t k = 0;; ++k) {
      std::size_t below = 0;
      for (std::size_t j = 0; j < n; ++j) below += before(j, k);
      if (below == n / 2) return k;
    }
  }
  scratch.clear();
  for (std::size_t k = 0; k < n; ++k) scratch.emplace_back(ranges[k], points[k]);
  std::nth_element(scratch.begin(), scratch.begin() + n / 2, scratch.end());
  return static_cast<std::size_t>(std::find(points, points + n, scratch[n / 2].second) - points);
}

}  // namespace cloudshape::segment::detail
