#include "synth/perturb.hpp"

#include <cmath>
#include <stdexcept>

namespace cloudshape::synth {

void add_gaussian_noise(PointList& points, double sigma, std::mt19937_64& rng) {
  if (!(sigma >= 0.0) || !std::isfinite(sigma))
    throw std::invalid_argument("noise sigma must be finite and >= 0");
  if (sigma == 0.0) return;
  std::normal_distribution<double> gauss(0.0, sigma);
  for (auto& p : points) p += Point(gauss(rng), gauss(rng), gauss(rng));
}

void add_outliers(PointList& points, double fraction, std::mt19937_64& rng) {
  if (!(fraction >= 0.0) || !std::isfinite(fraction))
    throw std::invalid_argument("outlier fraction must be finite and >= 0");
  if (points.empty()) return;
  const auto count = static_cast<std::size_t>(std::llround(fraction * points.size()));

  Point lo = points.front(), hi = points.front();
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // A flat cloud would give a zero-thickness box; borrow a margin from the largest extent.
  const Point extent = hi - lo;
  const double fallback = 0.05 * std::max(extent.maxCoeff(), 1e-12);
  for (int k = 0; k < 3; ++k) {
    const double margin = extent[k] > 0.0 ? 0.05 * extent[k] : fallback;
    lo[k] -= margin;
    hi[k] += margin;
  }

  std::uniform_real_distribution<double> u(0.0, 1.0);
  points.reserve(points.size() + count);
  for (std::size_t i = 0; i < count; ++i)
    points.emplace_back(lo.x() + u(rng) * (hi.x() - lo.x()), lo.y() + u(rng) * (hi.y() - lo.y()),
                        lo.z() + u(rng) * (hi.z() - lo.z()));
}

}  // namespace cloudshape::synth
