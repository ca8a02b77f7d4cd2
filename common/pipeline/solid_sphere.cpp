#include <algorithm>
#include <cmath>

#include "geometry/circle.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

// Least squares pulls a sphere towards whatever else is in its cloud (the stand a calibration
// sphere sits on, a patch of ground): refit on the points within the larger of the inlier
// distance and three median residuals, until that set stops changing. A clean sphere keeps all
// its points and so its first fit.
std::optional<geometry::SphereFit> trimmed_sphere_fit(const PointList& cloud, double inlier_distance) {
  auto fit = geometry::fit_sphere(cloud);
  std::size_t used = cloud.size();
  std::vector<double> residual(cloud.size());
  for (int round = 0; round < 5 && fit; ++round) {
    for (std::size_t i = 0; i < cloud.size(); ++i) residual[i] = std::abs((cloud[i] - fit->center).norm() - fit->radius);
    std::vector<double> sorted = residual;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double limit = std::max(inlier_distance, 3.0 * sorted[sorted.size() / 2]);
    std::vector<std::uint32_t> inliers;
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (residual[i] < limit) inliers.push_back(static_cast<std::uint32_t>(i));
    if (inliers.size() == used || inliers.size() < 4) break;
    const auto refit = geometry::fit_sphere(cloud, inliers);
    if (!refit) break;
    fit = refit;
    used = inliers.size();
  }
  return fit;
}

}  // namespace

std::optional<FittedSolid> fit_sphere_solid(const SolveInput& in) {
  const auto fit = trimmed_sphere_fit(in.cloud, in.cfg.inlier_distance * in.resolution);
  if (!fit) return std::nullopt;
  FittedSolid out;
  out.shape = Shape::sphere;
  out.dimensions = {{"radius", fit->radius}};
  out.center = fit->center;
  const Point c = fit->center;
  const double r = fit->radius;
  out.signed_distance = [c, r](const Point& p) { return (p - c).norm() - r; };
  return out;
}

}  // namespace cloudshape::pipeline
