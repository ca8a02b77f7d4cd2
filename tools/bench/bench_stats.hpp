// Order statistics of a set of timings (bench helper).
#pragma once

#include <vector>

namespace cloudshape::bench {

struct Summary {
  double median = 0.0;
  double p10 = 0.0;
  double p90 = 0.0;
  double min = 0.0;
  double max = 0.0;
};

// Percentile q in [0, 1] with linear interpolation between order statistics
// (q = 0.5 on an even count is the mean of the middle two). 0 for an empty set.
double percentile(std::vector<double> values, double q);

Summary summarize(const std::vector<double>& values);

}  // namespace cloudshape::bench
