#include <algorithm>
#include <cmath>

#include "geometry/circle.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

// Least squares pulls a sphere towards whatever else is in its cloud (the stand a calibration
// sphere sits on, a patch of ground): refit on the points within the larger of the inlier
// distance and three median residuals, until that set stops changing. The rounds run on about
// kTrimSample points (a fit over every point costs milliseconds, and every cloud is tried as
// a sphere). A clean sphere keeps all its points and so its first, full fit.
constexpr std::size_t kTrimSample = 1000;

std::vector<std::uint32_t> within(const PointList& points, const geometry::SphereFit& fit, double limit) {
  std::vector<std::uint32_t> kept;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::abs((points[i] - fit.center).norm() - fit.radius) < limit) kept.push_back(static_cast<std::uint32_t>(i));
  return kept;
}

std::optional<geometry::SphereFit> trimmed_sphere_fit(const PointList& cloud, double inlier_distance) {
  const auto first = geometry::fit_sphere(cloud);
  if (!first) return first;
  const std::size_t stride = std::max<std::size_t>(1, cloud.size() / kTrimSample);
  PointList sample;
  for (std::size_t i = 0; i < cloud.size(); i += stride) sample.push_back(cloud[i]);
  auto fit = first;
  std::size_t used = sample.size();
  bool trimmed = false;
  std::vector<double> residual(sample.size());
  for (int round = 0; round < 5; ++round) {
    for (std::size_t i = 0; i < sample.size(); ++i) residual[i] = std::abs((sample[i] - fit->center).norm() - fit->radius);
    std::nth_element(residual.begin(), residual.begin() + residual.size() / 2, residual.end());
    const double limit = std::max(inlier_distance, 3.0 * residual[residual.size() / 2]);
    const std::vector<std::uint32_t> inliers = within(sample, *fit, limit);
    if (inliers.size() == used || inliers.size() < 4) break;
    const auto refit = geometry::fit_sphere(sample, inliers);
    if (!refit) break;
    fit = refit;
    used = inliers.size();
    trimmed = true;
  }
  return trimmed ? fit : first;
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
