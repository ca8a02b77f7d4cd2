// Triangle meshes of the solids RViz has no primitive for, in the solid's own frame (x its axis),
// each face wound counter-clockwise seen from outside.
#include "ros2/detail/solid_meshes.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/polygon.hpp"

namespace cloudshape::ros2::detail {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

Triangles revolved(double base_radius, double top_radius, double height, int segments) {
  segments = std::max(segments, 3);
  const auto rim = [&](double x, double r, int k) {
    const double t = 2.0 * kPi * k / segments;
    return Eigen::Vector3d(x, r * std::cos(t), r * std::sin(t));
  };
  const Eigen::Vector3d base(0, 0, 0), top(height, 0, 0);
  Triangles out;
  for (int k = 0; k < segments; ++k) {
    const Eigen::Vector3d b0 = rim(0, base_radius, k), b1 = rim(0, base_radius, k + 1);
    const Eigen::Vector3d t0 = rim(height, top_radius, k), t1 = rim(height, top_radius, k + 1);
    out.insert(out.end(), {base, b1, b0});
    out.insert(out.end(), {b0, b1, t1});
    if (top_radius > 0.0) {
      out.insert(out.end(), {b0, t1, t0});
      out.insert(out.end(), {top, t0, t1});
    }
  }
  return out;
}

Triangles prism(const std::vector<Eigen::Vector2d>& polygon, double height) {
  if (polygon.size() < 3) return {};
  std::vector<Eigen::Vector2d> ccw = polygon;
  if (geometry::signed_area(ccw) < 0.0) std::reverse(ccw.begin(), ccw.end());
  const double h = 0.5 * height;
  const auto at = [&](double x, std::size_t i) { return Eigen::Vector3d(x, ccw[i].x(), ccw[i].y()); };
  Triangles out;
  for (const auto& t : geometry::triangulate(ccw)) {
    out.insert(out.end(), {at(h, t[0]), at(h, t[1]), at(h, t[2])});
    out.insert(out.end(), {at(-h, t[0]), at(-h, t[2]), at(-h, t[1])});
  }
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const std::size_t j = (i + 1) % ccw.size();
    out.insert(out.end(), {at(-h, i), at(-h, j), at(h, j)});
    out.insert(out.end(), {at(-h, i), at(h, j), at(h, i)});
  }
  return out;
}

Triangles tetrahedron(const std::array<Eigen::Vector3d, 4>& vertices) {
  Triangles out;
  for (std::size_t f = 0; f < 4; ++f) {
    std::array<Eigen::Vector3d, 3> face;
    for (std::size_t v = 0, k = 0; v < 4; ++v) {
      if (v != f) face[k++] = vertices[v];
    }
    const Eigen::Vector3d normal = (face[1] - face[0]).cross(face[2] - face[0]);
    if (normal.dot(vertices[f] - face[0]) > 0.0) std::swap(face[1], face[2]);
    out.insert(out.end(), face.begin(), face.end());
  }
  return out;
}

}  // namespace cloudshape::ros2::detail
