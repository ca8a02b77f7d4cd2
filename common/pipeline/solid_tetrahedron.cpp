// Tetrahedron from its faces: any tetrahedron from its four (a whole cloud), a regular one also
// from two or three (a single view: 70.5 deg fixes the rest, the points' ends the hidden faces).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "pipeline/solids.hpp"
#include "pipeline/tetrahedron_two_faces.hpp"

namespace cloudshape::pipeline {
namespace {

// Outward face normals of a regular tetrahedron: every two have dot -1/3 (faces meet at
// 70.53 deg). With these four normals any four offsets bound a regular tetrahedron.
const std::array<Eigen::Vector3d, 4>& canonical_normals() {
  static const std::array<Eigen::Vector3d, 4> n = {
      Eigen::Vector3d(1, 1, 1).normalized(), Eigen::Vector3d(1, -1, -1).normalized(),
      Eigen::Vector3d(-1, 1, -1).normalized(), Eigen::Vector3d(-1, -1, 1).normalized()};
  return n;
}

bool tetrahedron_angle(const DetectedPlane& a, const DetectedPlane& b, double tolerance) {
  return std::abs(a.plane.normal.dot(b.plane.normal) + 1.0 / 3.0) <= tolerance;
}

// The largest set (by points) of at most four faces that meet pairwise as a tetrahedron's.
std::vector<const DetectedPlane*> tetrahedron_faces(const std::vector<const DetectedPlane*>& faces,
                                                    double tolerance) {
  std::vector<const DetectedPlane*> best;
  std::size_t best_points = 0;
  for (std::size_t seed = 0; seed < faces.size(); ++seed) {
    std::vector<const DetectedPlane*> set{faces[seed]};
    std::size_t points = faces[seed]->inliers.size();
    for (std::size_t k = 0; k < faces.size() && set.size() < 4; ++k) {
      if (k == seed) continue;
      bool fits = true;
      for (const DetectedPlane* f : set) fits = fits && tetrahedron_angle(*f, *faces[k], tolerance);
      if (!fits) continue;
      set.push_back(faces[k]);
      points += faces[k]->inliers.size();
    }
    if (set.size() >= 2 && points > best_points) {
      best = set;
      best_points = points;
    }
  }
  return best;
}

// The rotation taking canonical normals 0..k-1 (in the order `slots`) onto the seen faces'
// normals, best in the least-squares sense weighted by each face's points (Kabsch).
Eigen::Matrix3d rotation_onto(const std::vector<const DetectedPlane*>& faces,
                              const std::array<int, 4>& slots, double& residual) {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < faces.size(); ++i)
    h.noalias() += static_cast<double>(faces[i]->inliers.size()) * faces[i]->plane.normal *
                   canonical_normals()[slots[i]].transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
  fix(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = svd.matrixU() * fix * svd.matrixV().transpose();
  residual = 0.0;
  for (std::size_t i = 0; i < faces.size(); ++i)
    residual += (r * canonical_normals()[slots[i]] - faces[i]->plane.normal).squaredNorm();
  return r;
}

// Face i is the one opposite vertex i, its normal pointing away from it.
std::array<geometry::Plane, 4> face_planes(const std::array<Point, 4>& vertices) {
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
  return planes;
}

FittedSolid make_tetrahedron(const std::array<Point, 4>& vertices, double regular_tolerance) {
  FittedSolid out;
  out.shape = Shape::tetrahedron;
  std::vector<double> edges;
  for (int a = 0; a < 4; ++a) {
    out.center += vertices[a] / 4.0;
    for (int b = a + 1; b < 4; ++b) edges.push_back((vertices[a] - vertices[b]).norm());
  }
  double edge_sum = 0.0;
  for (double e : edges) edge_sum += e;
  const double mean = edge_sum / 6.0;
  out.dimensions.emplace_back("edge", mean);
  out.vertices.assign(vertices.begin(), vertices.end());
  out.regular = std::all_of(edges.begin(), edges.end(),
                            [&](double e) { return std::abs(e - mean) <= regular_tolerance * mean; });
  const Eigen::Vector3d x = (vertices[0] - out.center).normalized();
  Eigen::Vector3d y = vertices[1] - out.center;
  y = (y - y.dot(x) * x).normalized();
  out.axes.row(0) = x.transpose();
  out.axes.row(1) = y.transpose();
  out.axes.row(2) = x.cross(y).transpose();
  const std::array<geometry::Plane, 4> planes = face_planes(vertices);
  out.signed_distance = [planes](const Point& p) {
    double d = -std::numeric_limits<double>::infinity();
    for (const auto& pl : planes) d = std::max(d, pl.signed_distance(p));
    return d;
  };
  return out;
}

// All four faces seen: vertex i is where the three faces other than face i meet.
std::optional<std::array<Point, 4>> from_four_faces(const std::vector<const DetectedPlane*>& four) {
  std::array<Point, 4> vertices;
  for (int skip = 0; skip < 4; ++skip) {
    std::array<const geometry::Plane*, 3> three{};
    for (int f = 0, k = 0; f < 4; ++f)
      if (f != skip) three[k++] = &four[f]->plane;
    const auto v = geometry::intersect_three_planes(*three[0], *three[1], *three[2]);
    if (!v) return std::nullopt;
    vertices[skip] = *v;
  }
  return vertices;
}

// Two or three faces seen (a single view): the exact tetrahedron normals closest to the
// seen ones; each seen face sits where its points are, and each hidden face where the
// points end along its normal. Every hidden face shares an edge with every seen one, and
// the seen faces are whole up to that edge, so the points do reach it.
std::optional<std::array<Point, 4>> from_seen_faces(const SolveInput& in,
                                           const std::vector<const DetectedPlane*>& seen) {
  // Two faces map onto canonical 0, 1 by a rotation either way round; three faces only in
  // one of their two cyclic orders (the other is a mirror image).
  std::array<int, 4> slots{0, 1, 2, 3};
  double residual = 0.0;
  Eigen::Matrix3d rotation = rotation_onto(seen, slots, residual);
  if (seen.size() == 3) {
    double mirrored_residual = 0.0;
    const std::array<int, 4> mirrored{0, 2, 1, 3};
    const Eigen::Matrix3d r = rotation_onto(seen, mirrored, mirrored_residual);
    if (mirrored_residual < residual) rotation = r, slots = mirrored;
  }
  std::array<geometry::Plane, 4> planes;
  std::array<bool, 4> placed{};
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const Eigen::Vector3d n = rotation * canonical_normals()[slots[i]];
    planes[slots[i]] = {n, -detail::face_position(in.cloud, *seen[i], n)};
    placed[slots[i]] = true;
  }
  for (int f = 0; f < 4; ++f) {
    if (placed[f]) continue;
    const Eigen::Vector3d n = rotation * canonical_normals()[f];
    planes[f] = {n, -detail::open_end_support(in, n)};
  }
  std::array<Point, 4> vertices;
  for (int skip = 0; skip < 4; ++skip) {
    std::array<int, 3> three{};
    for (int f = 0, k = 0; f < 4; ++f)
      if (f != skip) three[k++] = f;
    const auto v = geometry::intersect_three_planes(planes[three[0]], planes[three[1]], planes[three[2]]);
    if (!v) return std::nullopt;
    vertices[skip] = *v;
  }
  // A face on the wrong side of the opposite vertex would turn the solid inside out.
  for (int f = 0; f < 4; ++f)
    if (!(planes[f].signed_distance(vertices[f]) < 0.0)) return std::nullopt;
  return vertices;
}

// Any tetrahedron seen whole: its four largest faces, pairwise far from parallel, bound it when
// each one's plane leaves the opposite corner inside.
std::optional<std::array<Point, 4>> from_largest_faces(const std::vector<const DetectedPlane*>& faces,
                                                       double cos_parallel) {
  if (faces.size() < 4) return std::nullopt;
  const std::vector<const DetectedPlane*> four(faces.begin(), faces.begin() + 4);
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t b = a + 1; b < 4; ++b)
      if (std::abs(four[a]->plane.normal.dot(four[b]->plane.normal)) > cos_parallel) return std::nullopt;
  const auto vertices = from_four_faces(four);
  if (!vertices) return std::nullopt;
  for (int f = 0; f < 4; ++f)
    if (!(four[f]->plane.signed_distance((*vertices)[f]) < 0.0)) return std::nullopt;
  return vertices;
}

// How far the seen faces' points miss filling the tetrahedron's faces along them: the largest
// |hull area / triangle area - 1| (infinite for a degenerate triangle).
double fill_error(const SolveInput& in, const std::array<Point, 4>& vertices,
                  const std::vector<const DetectedPlane*>& seen) {
  const std::array<geometry::Plane, 4> planes = face_planes(vertices);
  double worst = 0.0;
  for (const DetectedPlane* f : seen) {
    int best = 0;
    for (int k = 1; k < 4; ++k)
      if (planes[k].normal.dot(f->plane.normal) > planes[best].normal.dot(f->plane.normal))
        best = k;
    std::array<Point, 3> tri;
    for (int v = 0, k = 0; v < 4; ++v)
      if (v != best) tri[k++] = vertices[v];
    const double triangle = 0.5 * (tri[1] - tri[0]).cross(tri[2] - tri[0]).norm();
    if (!(triangle > 0.0)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(detail::face_hull_area(in.cloud, *f) / triangle - 1.0));
  }
  return worst;
}

}  // namespace

std::optional<FittedSolid> fit_tetrahedron(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  const double tolerance = std::sin(in.cfg.parallel_degrees * 3.14159265358979323846 / 180.0);
  const auto seen = tetrahedron_faces(faces, tolerance);
  std::optional<std::array<Point, 4>> vertices;
  if (seen.size() == 4) vertices = from_four_faces(seen);
  // An irregular one meets at other angles: its four faces, when the cloud shows them all.
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * 3.14159265358979323846 / 180.0);
  if (!vertices) vertices = from_largest_faces(faces, cos_parallel);
  // Two or three faces seen: at a regular one's angles, the regular tetrahedron they fix; any
  // tetrahedron from the two largest when both are whole triangles. An irregular one may meet at
  // a regular one's angles too: a regular reading whose faces the seen points do not fill
  // (within solve.triangle_fill_tolerance) gives way to the other where that fills them closer.
  // Alone in its cloud, nothing hides part of a face the object shows (and a tetrahedron hides
  // none of its own): a regular reading no seen face fills, with no other reading, is no
  // tetrahedron (two sides of a star prism 108 degrees apart, each a rectangle a third of the
  // triangle's area, passed for a regular tetrahedron explaining half the points).
  if (!vertices) {
    const auto regular = seen.size() >= 2 ? from_seen_faces(in, seen) : std::nullopt;
    const auto any = detail::tetrahedron_from_two_faces(in, faces, cos_parallel);
    vertices = regular ? regular : any;
    if (regular && any) {
      const double regular_error = fill_error(in, *regular, seen);
      if (regular_error > in.cfg.triangle_fill_tolerance &&
          fill_error(in, *any, seen) < regular_error)
        vertices = any;
    } else if (regular && in.alone &&
               fill_error(in, *regular, seen) > in.cfg.triangle_fill_tolerance) {
      return std::nullopt;
    }
  }
  if (!vertices) return std::nullopt;
  std::vector<Eigen::Vector3d> normals;
  for (const geometry::Plane& p : face_planes(*vertices)) normals.push_back(p.normal);
  const auto on_faces = detail::points_on_planes_along(in.planes, normals, in.cfg.parallel_degrees);
  if (static_cast<double>(on_faces) < in.cfg.polyhedron_face_share * static_cast<double>(in.cloud.size()))
    return std::nullopt;
  const double cos_along = std::cos(in.cfg.stray_face_degrees * 3.14159265358979323846 / 180.0);
  // A tetrahedron has no two parallel faces: an octahedron's opposite faces or a pyramid's fifth
  // (along none of its four outward normals) say the four were picked from a solid with more.
  if (detail::stray_face_share(faces, normals, cos_along) > in.cfg.stray_face_share) return std::nullopt;
  return make_tetrahedron(*vertices, in.cfg.regular_tolerance);
}

}  // namespace cloudshape::pipeline
