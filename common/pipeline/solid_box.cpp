#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

#include "geometry/pca.hpp"
#include "pipeline/face_outline.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Best rotation taking the unit axes onto the face normals assigned to them (orthogonal
// Procrustes): uses every face, not only the two that seeded the frame.
Eigen::Matrix3d refine_frame(const Eigen::Matrix3d& frame,
                             const std::vector<const DetectedPlane*>& faces, double cos_parallel) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const DetectedPlane* f : faces) {
    for (int k = 0; k < 3; ++k) {
      const double c = f->plane.normal.dot(frame.col(k));
      if (std::abs(c) < cos_parallel) continue;
      const double w = static_cast<double>(f->inliers.size());
      m.noalias() += w * (c > 0 ? 1.0 : -1.0) * f->plane.normal * Eigen::Vector3d::Unit(k).transpose();
    }
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d r = svd.matrixU() * svd.matrixV().transpose();
  if (r.determinant() < 0) {
    Eigen::Matrix3d u = svd.matrixU();
    u.col(2) = -u.col(2);
    r = u * svd.matrixV().transpose();
  }
  return r.allFinite() ? r : frame;
}

// A box's six face directions: its three axes, either sign.
std::vector<Eigen::Vector3d> face_directions(const Eigen::Matrix3d& frame) {
  std::vector<Eigen::Vector3d> directions;
  for (int k = 0; k < 3; ++k) directions.insert(directions.end(), {frame.col(k), -frame.col(k)});
  return directions;
}

// A box's faces are rectangles: a face whose outline fills less of its smallest enclosing
// rectangle (a triangle fills half) is a prism's cap, a tetrahedron's or a pyramid's face. The
// outline is the convex hull, so the holes and ragged fill of a real sensor's partial face do not
// count; only a cut corner does, and mildly. In a scene a neighbour may hide part of a small face
// (a corner of it cut away leaves less than a rectangle): there only faces holding a fair share
// of the face points are judged. An object alone in its cloud has nothing beside it to hide part
// of a face, and a convex box hides none of the faces it shows: every face is judged, down to a
// prism's cap seen at a grazing angle (a few per cent of the points, a whole triangle). A face
// is judged with every face along the same box direction (`directions`, within acos(cos_parallel))
// lying within the step depth of it (detail::step_depth):
// RANSAC cuts a real box's bulging face into pieces a few millimetres apart, and a piece cut
// across the face is no rectangle of its own; face_is_step takes such pieces for one face too.
bool faces_are_rectangles(const SolveInput& in, const std::vector<const DetectedPlane*>& faces,
                          const std::vector<Eigen::Vector3d>& directions, double cos_parallel) {
  std::size_t all = 0;
  for (const DetectedPlane* f : faces) all += f->inliers.size();
  const double min_share = in.alone ? 0.0 : in.cfg.box_outline_min_share;
  for (const DetectedPlane* f : faces) {
    if (static_cast<double>(f->inliers.size()) < min_share * static_cast<double>(all)) continue;
    DetectedPlane face = *f;
    for (const Eigen::Vector3d& d : directions) {
      if (f->plane.normal.dot(d) < cos_parallel) continue;
      const double depth = detail::step_depth(in, d);
      const double at = detail::face_position(in.cloud, *f, d);
      for (const DetectedPlane* g : faces)
        if (g != f && detail::piece_of_face(in.cloud, *g, d, at, depth, cos_parallel))
          face.inliers.insert(face.inliers.end(), g->inliers.begin(), g->inliers.end());
      break;
    }
    const FaceOutline o = face_outline(in.cloud, face, 0.0, 0.0, 1.0);
    if (o.rect_fill > 0.0 && o.rect_fill < in.cfg.box_face_rect_fill) return false;
  }
  return true;
}

}  // namespace

std::optional<FittedSolid> fit_box(const SolveInput& in) {
  const auto faces = detail::faces_by_size(in.planes);
  if (faces.empty()) return std::nullopt;
  const double sin_perp = std::sin(in.cfg.perpendicular_degrees * kPi / 180.0);
  const double cos_parallel = std::cos(in.cfg.parallel_degrees * kPi / 180.0);

  const Eigen::Vector3d a0 = faces[0]->plane.normal;
  Eigen::Vector3d a1 = Eigen::Vector3d::Zero();
  for (std::size_t k = 1; k < faces.size() && a1.isZero(); ++k) {
    const Eigen::Vector3d n = faces[k]->plane.normal;
    if (std::abs(n.dot(a0)) < sin_perp) a1 = (n - n.dot(a0) * a0).normalized();
  }
  if (a1.isZero()) {
    // Two large faces at a slant are no box's (a tetrahedron's or prism's side seen alone).
    for (std::size_t k = 1; k < faces.size(); ++k)
      if (faces[k]->inliers.size() * 4 >= faces[0]->inliers.size() &&
          std::abs(faces[k]->plane.normal.dot(a0)) < cos_parallel)
        return std::nullopt;
    // One face seen: the in-plane spread of the points gives the other two directions, and the
    // depth only points off it measure: fewer than cfg.box_depth_min_share are the face's own
    // noise and flying pixels (a tetrahedron's face 1.4 m off, its plane whole in the noise band,
    // passed for a box 3.7 cm deep on 4% of its points).
    if (static_cast<double>(in.cloud.size() - std::min(in.cloud.size(), faces[0]->inliers.size())) <
        in.cfg.box_depth_min_share * static_cast<double>(in.cloud.size()))
      return std::nullopt;
    const geometry::Pca pca = geometry::compute_pca(in.cloud);
    Eigen::Vector3d best = pca.eigenvectors.col(2);
    best -= best.dot(a0) * a0;
    if (best.norm() < 1e-6) return std::nullopt;
    a1 = best.normalized();
  }
  Eigen::Matrix3d frame;
  frame.col(0) = a0;
  frame.col(1) = a1;
  frame.col(2) = a0.cross(a1);
  frame = refine_frame(frame, faces, cos_parallel);
  // Faces along none of the box's axes (a tetrahedron's slants, a triangular prism's second
  // side) say the box is only the points' bounding frame.
  if (detail::stray_face_share(faces, face_directions(frame), std::cos(in.cfg.stray_face_degrees * kPi / 180.0)) >
      in.cfg.stray_face_share)
    return std::nullopt;
  if (!faces_are_rectangles(in, faces, face_directions(frame), cos_parallel)) return std::nullopt;
  if (detail::slanted_neighbour_face(in, faces, face_directions(frame), std::cos(in.cfg.stray_face_degrees * kPi / 180.0)) ||
      detail::face_is_step(in, faces, face_directions(frame), cos_parallel))
    return std::nullopt;

  std::array<double, 3> lo{}, hi{};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = frame.col(k);
    double min_t = std::numeric_limits<double>::infinity(), max_t = -min_t;
    for (const Point& p : in.cloud) {
      min_t = std::min(min_t, p.dot(axis));
      max_t = std::max(max_t, p.dot(axis));
    }
    // A face bounds the points: the end of their range it lies nearer is its side of the box.
    // Not its normal's sign: segment_planes turns a normal away from the cloud's centroid, which a
    // view of mostly one face puts in that face, and a real box's bulging face, cut into pieces,
    // then had pieces on both sides (a box 2.4 mm deep, no box).
    double face_lo = std::numeric_limits<double>::quiet_NaN(), face_hi = face_lo;
    for (const DetectedPlane* f : faces) {
      const double c = f->plane.normal.dot(axis);
      if (std::abs(c) < cos_parallel) continue;
      const double pos = detail::face_position(in.cloud, *f, axis);
      if (max_t - pos < pos - min_t)
        face_hi = std::isnan(face_hi) ? pos : std::max(face_hi, pos);
      else face_lo = std::isnan(face_lo) ? pos : std::min(face_lo, pos);
    }
    const double slab = std::max(in.cfg.face_slab * (max_t - min_t), 2.0 * in.resolution);
    std::tie(lo[k], hi[k]) = detail::slab_median_extent(in.cloud, axis, slab, face_lo, face_hi,
                                                          in.cfg.open_end_quantile);
  }
  // Thinner than twice the verification band, every point lies within the band of both large
  // faces: the third dimension is not measured, and one face seen is any flat-faced solid's.
  for (int k = 0; k < 3; ++k)
    if (hi[k] - lo[k] < 2.0 * in.cfg.inlier_distance * in.resolution) return std::nullopt;
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });

  FittedSolid out;
  out.shape = Shape::box;
  const char* names[3] = {"length", "width", "height"};
  Eigen::Vector3d half;
  for (int r = 0; r < 3; ++r) {
    const int k = order[r];
    out.dimensions.emplace_back(names[r], hi[k] - lo[k]);
    out.axes.row(r) = frame.col(k).transpose();
    out.center += 0.5 * (lo[k] + hi[k]) * frame.col(k);
    half[r] = 0.5 * (hi[k] - lo[k]);
  }
  out.axes.row(2) = out.axes.row(0).cross(out.axes.row(1));
  const Eigen::Matrix3d axes = out.axes;
  const Point c = out.center;
  out.signed_distance = [axes, c, half](const Point& p) {
    const Eigen::Vector3d local = axes * (p - c);
    return (local.cwiseAbs() - half).maxCoeff();
  };
  return out;
}

}  // namespace cloudshape::pipeline
