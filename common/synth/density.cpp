#include "synth/density.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cloudshape::synth {

namespace {

constexpr int kPatches = 6;

}  // namespace

PointList thin_by_density(const PointList& points, const DensityVariation& variation,
                          std::mt19937_64& rng) {
  if (!(variation.patchiness >= 0.0 && variation.patchiness <= 1.0))
    throw std::invalid_argument("patchiness must be within [0, 1]");
  if (points.empty() || !variation.active()) return points;

  double nearest_sq = std::numeric_limits<double>::infinity();
  if (variation.falloff_from)
    for (const auto& p : points) nearest_sq = std::min(nearest_sq, (p - *variation.falloff_from).squaredNorm());

  std::vector<Point> centres;
  double radius = 0.0;
  if (variation.patchiness > 0.0) {
    Point lo = points.front(), hi = points.front();
    for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    radius = 0.2 * (hi - lo).norm();
    std::uniform_int_distribution<std::size_t> pick(0, points.size() - 1);
    for (int k = 0; k < kPatches; ++k) centres.push_back(points[pick(rng)]);
  }

  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointList kept;
  kept.reserve(points.size());
  for (const auto& p : points) {
    double keep = 1.0;
    if (variation.falloff_from) {
      const double d_sq = (p - *variation.falloff_from).squaredNorm();
      keep *= d_sq > 0.0 ? std::min(1.0, nearest_sq / d_sq) : 1.0;
    }
    double loss = 0.0;  // the deepest patch the point lies in
    for (const auto& c : centres) {
      const double t_sq = (p - c).squaredNorm() / (radius * radius);
      if (t_sq < 1.0) loss = std::max(loss, (1.0 - t_sq) * (1.0 - t_sq));
    }
    keep *= 1.0 - variation.patchiness * loss;
    if (u(rng) < keep) kept.push_back(p);
  }
  return kept;
}

}  // namespace cloudshape::synth
