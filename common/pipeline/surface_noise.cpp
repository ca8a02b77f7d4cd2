#include "pipeline/surface_noise.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

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
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::uint32_t j : near) mean += points[j];
    mean /= static_cast<double>(near.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (std::uint32_t j : near) {
      const Eigen::Vector3d d = points[j] - mean;
      scatter += d * d.transpose();
    }
    scatter /= static_cast<double>(near.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter, Eigen::EigenvaluesOnly);
    spreads.push_back(std::sqrt(std::max(0.0, eigen.eigenvalues()(0))));
  }
  const auto quartile = spreads.begin() + static_cast<std::ptrdiff_t>((spreads.size() - 1) / 4);
  std::nth_element(spreads.begin(), quartile, spreads.end());
  return *quartile;
}

}  // namespace cloudshape::pipeline
