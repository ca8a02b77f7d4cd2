#include "pipeline/scan_fit.hpp"

#include <cmath>
#include <vector>

#include "geometry/kdtree.hpp"
#include "geometry/robust_spread.hpp"

namespace cloudshape::pipeline {

double scan_line_noise(const PointList& cloud, const Point& viewpoint) {
  PointList directions;
  std::vector<double> ranges;
  directions.reserve(cloud.size());
  ranges.reserve(cloud.size());
  for (const Point& p : cloud) {
    const double range = (p - viewpoint).norm();
    if (!(range > 0.0)) continue;
    directions.push_back((p - viewpoint) / range);
    ranges.push_back(range);
  }
  if (directions.size() < 3) return 0.0;
  const geometry::KdTree tree(directions);
  std::vector<double> deviations;
  deviations.reserve(directions.size());
  std::vector<std::uint32_t> near;
  for (std::uint32_t i = 0; i < directions.size(); ++i) {
    tree.knn(directions[i], 3, near);
    if (near.size() < 3) continue;
    // The two nearest others (a repeated direction may come before the point itself).
    std::uint32_t pair[2];
    int found = 0;
    for (std::uint32_t j : near)
      if (j != i && found < 2) pair[found++] = j;
    if (found < 2) continue;
    const Eigen::Vector3d to_a = directions[pair[0]] - directions[i];
    const Eigen::Vector3d to_b = directions[pair[1]] - directions[i];
    if (to_a.dot(to_b) >= 0.0) continue;
    const double da = to_a.norm(), db = to_b.norm();
    const double t = da / (da + db);  // where the point lies between a (0) and b (1)
    const double expected = ranges[pair[0]] + t * (ranges[pair[1]] - ranges[pair[0]]);
    // The difference holds the point's noise and t and 1 - t of the neighbours'.
    deviations.push_back(std::abs(ranges[i] - expected) /
                         std::sqrt(1.0 + t * t + (1.0 - t) * (1.0 - t)));
  }
  if (deviations.size() < 3) return 0.0;
  return geometry::robust_deviation(std::move(deviations));
}

double scatter_about(const PointList& cloud, const FittedSolid& solid) {
  std::vector<double> distances;
  distances.reserve(cloud.size());
  for (const Point& p : cloud) distances.push_back(std::abs(solid.signed_distance(p)));
  return geometry::robust_deviation(std::move(distances));
}

}  // namespace cloudshape::pipeline
