#include "synth/mesh_solids.hpp"

#include <algorithm>
#include <cmath>

namespace cloudshape::synth {

SolidMesh frustum_mesh(double radius, double top_radius, double height, const Pose& pose, int segments) {
  constexpr double kPi = 3.14159265358979323846;
  SolidMesh m;
  const auto n = static_cast<std::uint32_t>(std::max(8, segments));
  for (std::uint32_t i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    m.vertices.push_back(pose.to_world({0.0, radius * std::cos(a), radius * std::sin(a)}));
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    m.vertices.push_back(pose.to_world({height, top_radius * std::cos(a), top_radius * std::sin(a)}));
  }
  const std::uint32_t bottom = 2 * n, top = 2 * n + 1;
  m.vertices.push_back(pose.to_world({0.0, 0.0, 0.0}));
  m.vertices.push_back(pose.to_world({height, 0.0, 0.0}));
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
    m.triangles.push_back({bottom, j, i});
    m.triangles.push_back({top, n + i, n + j});
  }
  // Centroid of the solid: h = H (R^2 + 2 R r + 3 r^2) / (4 (R^2 + R r + r^2)) above the base.
  const double R = radius, r = top_radius;
  const double h = height * (R * R + 2 * R * r + 3 * r * r) / (4.0 * (R * R + R * r + r * r));
  m.center = pose.to_world({h, 0.0, 0.0});
  m.size = std::max(2.0 * radius, height);
  return m;
}

SolidMesh prism_mesh(const geometry::Polygon2& polygon, double height, const Pose& pose) {
  SolidMesh m;
  const auto n = static_cast<std::uint32_t>(polygon.size());
  for (double x : {-0.5 * height, 0.5 * height})
    for (const auto& p : polygon) m.vertices.push_back(pose.to_world({x, p.x(), p.y()}));
  for (const auto& t : geometry::triangulate(polygon)) {
    const auto a = static_cast<std::uint32_t>(t[0]), b = static_cast<std::uint32_t>(t[1]), c = static_cast<std::uint32_t>(t[2]);
    m.triangles.push_back({n + a, n + b, n + c});
    m.triangles.push_back({a, c, b});
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
  }
  double extent = 0.0;
  for (const auto& a : polygon)
    for (const auto& b : polygon) extent = std::max(extent, (a - b).norm());
  m.center = pose.center;
  m.size = std::max(extent, height);
  return m;
}

SolidMesh tetrahedron_mesh(const std::array<Eigen::Vector3d, 4>& corners) {
  SolidMesh m;
  m.vertices.assign(corners.begin(), corners.end());
  m.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  for (const auto& c : corners) m.center += c / 4.0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) m.size = std::max(m.size, (corners[a] - corners[b]).norm());
  return m;
}

}  // namespace cloudshape::synth
