// The fixed-seed test clouds of cloudshape-bench --accuracy, one condition at a time.
// Clouds are built on demand by index so a suite never holds more than one cloud in memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "accuracy_score.hpp"

namespace cloudshape::bench {

struct SuiteOptions {
  int count = 30;           // clouds per shape (synthetic conditions)
  std::uint64_t seed = 42;  // every cloud's randomness derives from it
  double solid_size = 100.0;
  // Synthetic clouds are drawn with 2k-200k points (log-uniform); a cloud drawn above this cap
  // gets the cap instead, so a smaller cap leaves every solid, pose and smaller cloud as it was.
  std::size_t max_points = 200000;
  std::string shared_data_dir;  // holds real/ (the YCB and ravens meshes)
};

// clean, noise, outliers, density, single_view, table_view, multi, real, negatives, new_shapes: the
// report's order.
const std::vector<std::string>& accuracy_conditions();

// One line per condition saying how its clouds are made (printed with the table).
std::string describe_condition(const std::string& condition);

// How many clouds the condition has: count per shape for the synthetic ones, the sample
// files present on disk for `real`.
std::size_t suite_size(const std::string& condition, const SuiteOptions& options);

// Cloud `index` (0 <= index < suite_size) of the condition. Throws std::invalid_argument for
// an unknown condition and whatever reading a real sample throws.
TestCloud make_test_cloud(const std::string& condition, std::size_t index,
                          const SuiteOptions& options);

}  // namespace cloudshape::bench
