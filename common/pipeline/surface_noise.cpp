#include "pipeline/surface_noise.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/pca.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr std::size_t kSamples = 2000;

}  // namespace

double surface_noise(const PointList& points, const geometry::KdTree& tree,
                     std::size_t neighbours) {
  if (neighbours < 4 || points.size() < neighbours) return 0.0;
  const std::size_t step = std::max<std::size_t>(1, points.size() / kSamples);
  std::vector<double> spreads;
  spreads.reserve(points.size() / step + 1);
  std::vector<std::uint32_t> near;
  for (std::size_t i = 0; i < points.size(); i += step) {
    tree.knn(points[i], neighbours, near);
    spreads.push_back(std::sqrt(geometry::compute_pca(points, near).eigenvalues(0)));
  }
  const auto quartile = spreads.begin() + static_cast<std::ptrdiff_t>((spreads.size() - 1) / 4);
  std::nth_element(spreads.begin(), quartile, spreads.end());
  return *quartile;
}

}  // namespace cloudshape::pipeline
