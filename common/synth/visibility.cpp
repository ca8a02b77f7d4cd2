#include "synth/visibility.hpp"

#include <algorithm>
#include <cmath>

namespace cloudshape::synth {

PointList sample_visible(const std::function<PointList(std::size_t)>& sample,
                         const std::function<PointList(const PointList&)>& keep_visible,
                         std::size_t n, std::mt19937_64& rng) {
  if (n == 0) return {};
  // Each pass estimates the visible fraction and oversamples by its inverse plus a margin;
  // the cap keeps a nearly invisible surface from exhausting memory.
  const double max_samples = 50.0 * static_cast<double>(n);
  std::size_t m = n;
  PointList visible;
  for (int pass = 0; pass < 4; ++pass) {
    visible = keep_visible(sample(m));
    if (visible.size() >= n || visible.empty() || static_cast<double>(m) >= max_samples) break;
    const double fraction = static_cast<double>(visible.size()) / static_cast<double>(m);
    m = static_cast<std::size_t>(
        std::min(max_samples, std::ceil(1.15 * static_cast<double>(n) / fraction)));
  }
  if (visible.size() <= n) return visible;
  // Partial Fisher-Yates: the first n entries become a uniform random subset.
  for (std::size_t i = 0; i < n; ++i) {
    std::uniform_int_distribution<std::size_t> pick(i, visible.size() - 1);
    std::swap(visible[i], visible[pick(rng)]);
  }
  visible.resize(n);
  return visible;
}

}  // namespace cloudshape::synth
