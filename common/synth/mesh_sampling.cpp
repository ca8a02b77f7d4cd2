#include "synth/mesh_sampling.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cloudshape::synth {

namespace {

double triangle_area(const PointList& v, const Triangle& t) {
  const double a = 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm();
  return std::isfinite(a) ? a : 0.0;
}

}  // namespace

void check_triangle_indices(const PointList& vertices, const std::vector<Triangle>& triangles) {
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t index : triangles[t])
      if (index >= vertices.size())
        throw std::invalid_argument("triangle " + std::to_string(t) + " refers to vertex " +
                                    std::to_string(index) + " but the mesh has only " +
                                    std::to_string(vertices.size()) + " vertices");
}

double mesh_area(const PointList& vertices, const std::vector<Triangle>& triangles) {
  check_triangle_indices(vertices, triangles);
  double total = 0.0;
  for (const auto& t : triangles) total += triangle_area(vertices, t);
  return total;
}

PointList sample_mesh_surface(const PointList& vertices, const std::vector<Triangle>& triangles,
                              std::size_t n, std::mt19937_64& rng) {
  check_triangle_indices(vertices, triangles);
  // Only triangles with area enter the table, so a zero-area one can never be chosen.
  std::vector<std::size_t> used;
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const double a = triangle_area(vertices, triangles[t]);
    if (a <= 0.0) continue;
    total += a;
    used.push_back(t);
    cumulative.push_back(total);
  }
  if (!(total > 0.0)) throw std::invalid_argument("mesh has zero total surface area");

  PointList out;
  out.reserve(n);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), u(rng) * total);
    const std::size_t k = std::min<std::size_t>(it - cumulative.begin(), used.size() - 1);
    const Triangle& t = triangles[used[k]];
    // Square root of u1 makes the barycentric density uniform over the triangle.
    const double s = std::sqrt(u(rng)), w = u(rng);
    out.push_back((1.0 - s) * vertices[t[0]] + s * (1.0 - w) * vertices[t[1]] +
                  s * w * vertices[t[2]]);
  }
  return out;
}

}  // namespace cloudshape::synth
