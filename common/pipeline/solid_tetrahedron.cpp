#include <algorithm>
#include <array>
#include <cmath>

#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

// Faces of a regular tetrahedron meet at 70.53 deg: outward normals have dot -1/3.
bool regular_angles(const std::vector<const DetectedPlane*>& faces, double tolerance) {
  for (std::size_t a = 0; a < faces.size(); ++a)
    for (std::size_t b = a + 1; b < faces.size(); ++b)
      if (std::abs(faces[a]->plane.normal.dot(faces[b]->plane.normal) + 1.0 / 3.0) > tolerance)
        return false;
  return true;
}

FittedSolid make_tetrahedron(const std::array<Point, 4>& vertices) {
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
  // Face i is the one opposite vertex i, oriented away from it.
  std::array<geometry::Plane, 4> planes;
  for (int f = 0; f < 4; ++f) {
    std::array<Point, 3> tri;
    for (int v = 0, k = 0; v < 4; ++v)
      if (v != f) tri[k++] = vertices[v];
    planes[f] = geometry::plane_through(tri[0], tri[1], tri[2]).value_or(geometry::Plane{});
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

// Three faces seen (a single view): they meet at a vertex, their pairwise lines are the
// three edges from it, and each edge is as long as the faces' points reach along it.
std::optional<FittedSolid> from_three_faces(const SolveInput& in,
                                            const std::vector<const DetectedPlane*>& faces) {
  const auto apex = geometry::intersect_three_planes(faces[0]->plane, faces[1]->plane, faces[2]->plane);
  if (!apex) return std::nullopt;
  std::array<Eigen::Vector3d, 3> edges;
  double length = 0.0;
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int e = 0; e < 3; ++e) {
    const auto line = geometry::intersect_planes(faces[pairs[e][0]]->plane, faces[pairs[e][1]]->plane);
    if (!line) return std::nullopt;
    std::vector<double> along;
    for (int side : pairs[e])
      for (std::uint32_t i : faces[side]->inliers) along.push_back((in.cloud[i] - *apex).dot(line->direction));
    double sum = 0.0;
    for (double t : along) sum += t;
    edges[e] = sum >= 0.0 ? line->direction : -line->direction;
    for (double& t : along) t = std::abs(t);
    const std::size_t top = along.size() - 1 - along.size() / 200;
    std::nth_element(along.begin(), along.begin() + top, along.end());
    length += along[top] / 3.0;
  }
  return make_tetrahedron({*apex, *apex + length * edges[0], *apex + length * edges[1],
                           *apex + length * edges[2]});
}

}  // namespace

std::optional<FittedSolid> fit_tetrahedron(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  const double tolerance = std::sin(in.cfg.parallel_degrees * 3.14159265358979323846 / 180.0);
  if (faces.size() >= 4) {
    const std::vector<const DetectedPlane*> four(faces.begin(), faces.begin() + 4);
    if (regular_angles(four, tolerance)) {
      // Vertex i is where the three faces other than face i meet.
      std::array<Point, 4> vertices;
      for (int skip = 0; skip < 4; ++skip) {
        std::array<const geometry::Plane*, 3> three{};
        for (int f = 0, k = 0; f < 4; ++f)
          if (f != skip) three[k++] = &four[f]->plane;
        const auto v = geometry::intersect_three_planes(*three[0], *three[1], *three[2]);
        if (!v) return std::nullopt;
        vertices[skip] = *v;
      }
      return make_tetrahedron(vertices);
    }
  }
  if (faces.size() >= 3) {
    const std::vector<const DetectedPlane*> three(faces.begin(), faces.begin() + 3);
    if (regular_angles(three, tolerance)) return from_three_faces(in, three);
  }
  return std::nullopt;
}

}  // namespace cloudshape::pipeline
