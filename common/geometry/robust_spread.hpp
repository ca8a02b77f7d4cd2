// Robust statistics of a set of values: their median, and a deviation from the median of
// distances (robust to the few points of another surface a plane's band takes in).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace cloudshape::geometry {

// The middle value (the upper of the two middle ones for an even count); 0 for none.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

// Absolute distances from a surface (or any absolute deviations) as a normal deviation: their
// median scaled by 1.4826 (a Gaussian's median absolute value is 1 / 1.4826 deviations).
inline double robust_deviation(std::vector<double> distances) {
  return 1.4826 * median(std::move(distances));
}

}  // namespace cloudshape::geometry
