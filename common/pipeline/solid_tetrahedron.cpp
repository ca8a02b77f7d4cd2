#include <array>
#include <cmath>

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

std::optional<FittedSolid> fit_tetrahedron(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  if (faces.size() < 4) return std::nullopt;
  // Faces of a regular tetrahedron meet at 70.53 deg: outward normals have dot -1/3.
  const double tolerance = std::sin(in.cfg.parallel_degrees * 3.14159265358979323846 / 180.0);
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (std::abs(faces[a]->plane.normal.dot(faces[b]->plane.normal) + 1.0 / 3.0) > tolerance)
        return std::nullopt;
  // Vertex i is where the three faces other than face i meet.
  std::array<Point, 4> vertices;
  for (int skip = 0; skip < 4; ++skip) {
    std::array<const geometry::Plane*, 3> three{};
    for (int f = 0, k = 0; f < 4; ++f)
      if (f != skip) three[k++] = &faces[f]->plane;
    const auto v = geometry::intersect_three_planes(*three[0], *three[1], *three[2]);
    if (!v) return std::nullopt;
    vertices[skip] = *v;
  }
  FittedSolid out;
  out.shape = Shape::tetrahedron;
  double edge_sum = 0.0;
  for (int a = 0; a < 4; ++a) {
    out.center += vertices[a] / 4.0;
    for (int b = a + 1; b < 4; ++b) edge_sum += (vertices[a] - vertices[b]).norm();
  }
  out.dimensions.emplace_back("edge", edge_sum / 6.0);
  const Eigen::Vector3d x = (vertices[0] - out.center).normalized();
  Eigen::Vector3d y = vertices[1] - out.center;
  y = (y - y.dot(x) * x).normalized();
  out.axes.row(0) = x.transpose();
  out.axes.row(1) = y.transpose();
  out.axes.row(2) = x.cross(y).transpose();
  std::array<geometry::Plane, 4> planes;
  for (int f = 0; f < 4; ++f) {
    planes[f] = faces[f]->plane;
    // Outward: away from the vertex that is not on this face.
    if (planes[f].signed_distance(vertices[f]) > 0) {
      planes[f].normal = -planes[f].normal;
      planes[f].offset = -planes[f].offset;
    }
  }
  out.signed_distance = [planes](const Point& p) {
    double d = -std::numeric_limits<double>::infinity();
    for (const auto& pl : planes) d = std::max(d, pl.signed_distance(p));
    return d;
  };
  return out;
}

}  // namespace cloudshape::pipeline
