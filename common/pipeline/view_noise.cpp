#include "pipeline/view_noise.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/kdtree.hpp"
#include "geometry/plane.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr std::size_t kSamples = 256;

}  // namespace

double noise_along_view(const PointList& points, const Point& viewpoint, std::size_t neighbours) {
  if (neighbours < 4 || points.size() < neighbours) return 0.0;
  // Unit directions: neighbours on the sphere of directions by chord, which orders as the angle.
  PointList directions;
  directions.reserve(points.size());
  for (const Point& p : points) {
    const Eigen::Vector3d ray = p - viewpoint;
    const double length = ray.norm();
    directions.push_back(length > 0.0 ? Point(ray / length) : Point::Zero());
  }
  const geometry::KdTree tree(directions);
  const std::size_t step = std::max<std::size_t>(1, points.size() / kSamples);
  std::vector<double> spreads;
  spreads.reserve(points.size() / step + 1);
  std::vector<std::uint32_t> near;
  for (std::size_t i = 0; i < points.size(); i += step) {
    tree.knn(directions[i], neighbours, near);
    Eigen::Vector3d u, v;
    geometry::plane_basis(directions[i], u, v);
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    for (std::uint32_t j : near) {
      const Eigen::Vector3d d = points[j] - points[i];
      const Eigen::Vector3d row(d.dot(u), d.dot(v), 1.0);
      normal_matrix += row * row.transpose();
      moment += row * d.dot(directions[i]);
    }
    const Eigen::Matrix3d inverse = normal_matrix.inverse();
    const Eigen::Vector3d plane = inverse * moment;
    if (!inverse.allFinite() || !plane.allFinite()) continue;
    double sum = 0.0;
    for (std::uint32_t j : near) {
      const Eigen::Vector3d d = points[j] - points[i];
      const double along =
          d.dot(directions[i]) - plane.x() * d.dot(u) - plane.y() * d.dot(v) - plane.z();
      sum += along * along;
    }
    const double along_ray = sum / static_cast<double>(near.size() - 3);
    // Off the surface the deviation along the ray shrinks with the cosine of the surface's slope
    // across it. The fitted slope carries the noise too (its variance from the fit): squared as it
    // stands it reads a face seen square on as tilted, and the noise an eighth low.
    const double tilt =
        plane.x() * plane.x() + plane.y() * plane.y() - along_ray * (inverse(0, 0) + inverse(1, 1));
    spreads.push_back(std::sqrt(along_ray / (1.0 + std::max(0.0, tilt))));
  }
  if (spreads.empty()) return 0.0;
  const auto median = spreads.begin() + static_cast<std::ptrdiff_t>(spreads.size() / 2);
  std::nth_element(spreads.begin(), median, spreads.end());
  return *median;
}

}  // namespace cloudshape::pipeline
