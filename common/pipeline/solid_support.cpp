#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "geometry/circle.hpp"
#include "geometry/kdtree.hpp"
#include "geometry/pca.hpp"
#include "pipeline/solids.hpp"

namespace cloudshape::pipeline {

const std::vector<detail::SurfaceSample>& SolveInput::cloud_normals() const {
  std::call_once(normals_once_, [this] {
    std::vector<std::uint32_t> all(cloud.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
    normals_ = detail::sample_normals(cloud, all, 1500, tree);
  });
  return normals_;
}

std::optional<FittedSolid> fit_solid(Shape shape, const SolveInput& in) {
  switch (shape) {
    case Shape::box: return fit_box(in);
    case Shape::tetrahedron: return fit_tetrahedron(in);
    case Shape::pentagonal_prism: return fit_pentagonal_prism(in);
    case Shape::cylinder: return fit_cylinder(in);
    case Shape::cone: return fit_cone(in);
    case Shape::sphere: return fit_sphere_solid(in);
    case Shape::frustum: return fit_frustum(in);
    case Shape::prism: return fit_prism(in);
    case Shape::unknown: break;
  }
  return std::nullopt;
}

namespace detail {

bool plausible(const FittedSolid& s, double cloud_diameter, double max_size_ratio) {
  if (!s.center.allFinite() || !s.axes.allFinite()) return false;
  for (const auto& [name, value] : s.dimensions)
    if (name != "sides" && (!(value > 0.0) || !std::isfinite(value) || value > max_size_ratio * cloud_diameter))
      return false;
  return true;
}

std::vector<const DetectedPlane*> faces_by_size(const PlaneSegmentation& planes) {
  std::vector<const DetectedPlane*> faces;
  for (const auto& p : planes.planes)
    if (p.is_face) faces.push_back(&p);
  std::stable_sort(faces.begin(), faces.end(), [](const DetectedPlane* a, const DetectedPlane* b) {
    return a->inliers.size() > b->inliers.size();
  });
  return faces;
}

double face_position(const PointList& cloud, const DetectedPlane& face, const Eigen::Vector3d& axis) {
  double sum = 0.0;
  for (std::uint32_t i : face.inliers) sum += cloud[i].dot(axis);
  return face.inliers.empty() ? 0.0 : sum / static_cast<double>(face.inliers.size());
}

std::vector<SurfaceSample> sample_normals(const PointList& cloud,
                                          const std::vector<std::uint32_t>& points,
                                          std::size_t max_samples, const geometry::KdTree* shared_tree) {
  std::vector<SurfaceSample> out;
  if (points.size() < 8) return out;
  std::optional<geometry::KdTree> own_tree;
  const geometry::KdTree& tree = shared_tree ? *shared_tree : own_tree.emplace(cloud);
  const std::size_t step = std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, max_samples));
  std::vector<std::uint32_t> nb;
  for (std::size_t k = 0; k < points.size(); k += step) {
    tree.knn(cloud[points[k]], 12, nb);
    out.push_back({cloud[points[k]], geometry::compute_pca(cloud, nb).eigenvectors.col(0).normalized()});
  }
  return out;
}

Eigen::Vector3d axis_from_normals(const std::vector<SurfaceSample>& samples) {
  if (samples.empty()) return Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const auto& s : samples) m.noalias() += s.normal * s.normal.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
  return solver.eigenvectors().col(0).normalized();
}

Eigen::Matrix3d frame_from_axis(const Eigen::Vector3d& axis) {
  Eigen::Vector3d u, v;
  geometry::plane_basis(axis, u, v);
  Eigen::Matrix3d out;
  out.row(0) = axis.normalized().transpose();
  out.row(1) = u.transpose();
  out.row(2) = axis.normalized().cross(u).transpose();
  return out;
}

std::pair<double, double> slab_median_extent(const PointList& cloud, const Eigen::Vector3d& axis,
                                             double slab, double face_lo, double face_hi,
                                             double open_quantile) {
  std::vector<double> t;
  t.reserve(cloud.size());
  for (const Point& p : cloud) t.push_back(p.dot(axis));
  if (t.empty()) return {0.0, 0.0};
  const auto [lo_it, hi_it] = std::minmax_element(t.begin(), t.end());
  const double lo_edge = std::isnan(face_lo) ? *lo_it + slab : face_lo + 0.5 * slab;
  const double hi_edge = std::isnan(face_hi) ? *hi_it - slab : face_hi - 0.5 * slab;
  std::vector<double> low, high;
  for (double x : t) {
    if (x <= lo_edge) low.push_back(x);
    if (x >= hi_edge) high.push_back(x);
  }
  // q: the share of the slab's points below the estimate (0.5: the median).
  auto quantile = [](std::vector<double>& v, double q, double fallback) {
    if (v.empty()) return fallback;
    const auto k = static_cast<std::size_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[k];
  };
  return {quantile(low, std::isnan(face_lo) ? 1.0 - open_quantile : 0.5, *lo_it),
          quantile(high, std::isnan(face_hi) ? open_quantile : 0.5, *hi_it)};
}

double open_end_support(const SolveInput& in, const Eigen::Vector3d& direction) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Point& p : in.cloud) {
    lo = std::min(lo, p.dot(direction));
    hi = std::max(hi, p.dot(direction));
  }
  const double slab = std::max(in.cfg.face_slab * (hi - lo), 2.0 * in.resolution);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return slab_median_extent(in.cloud, direction, slab, nan, nan, in.cfg.open_end_quantile).second;
}

Eigen::Vector3d extrusion_axis(const std::vector<const DetectedPlane*>& sides,
                               const std::vector<const DetectedPlane*>& caps, const Eigen::Vector3d& hint) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const DetectedPlane* f : sides)
    m.noalias() += static_cast<double>(f->inliers.size()) * f->plane.normal * f->plane.normal.transpose();
  for (const DetectedPlane* f : caps)
    m.noalias() -= static_cast<double>(f->inliers.size()) * f->plane.normal * f->plane.normal.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m);
  Eigen::Vector3d axis = solver.eigenvectors().col(0).normalized();
  return axis.dot(hint) < 0 ? Eigen::Vector3d(-axis) : axis;
}

std::pair<double, double> extrusion_extent(const SolveInput& in,
                                           const std::vector<const DetectedPlane*>& caps,
                                           const Eigen::Vector3d& axis) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double cap_lo = nan, cap_hi = nan;
  for (const DetectedPlane* f : caps) {
    double& cap = f->plane.normal.dot(axis) > 0 ? cap_hi : cap_lo;
    if (std::isnan(cap)) cap = face_position(in.cloud, *f, axis);
  }
  double lo = 0.0, hi = 0.0;
  if (std::isnan(cap_lo) || std::isnan(cap_hi)) {
    double min_t = std::numeric_limits<double>::infinity(), max_t = -min_t;
    for (const Point& p : in.cloud) {
      min_t = std::min(min_t, p.dot(axis));
      max_t = std::max(max_t, p.dot(axis));
    }
    const double slab = std::max(in.cfg.face_slab * (max_t - min_t), 2.0 * in.resolution);
    std::tie(lo, hi) = slab_median_extent(in.cloud, axis, slab, nan, nan, in.cfg.open_end_quantile);
  }
  if (!std::isnan(cap_lo)) lo = cap_lo;
  if (!std::isnan(cap_hi)) hi = cap_hi;
  return {lo, hi};
}

std::size_t points_on_planes_along(const PlaneSegmentation& planes,
                                   const std::vector<Eigen::Vector3d>& normals, double degrees) {
  const double min_cos = std::cos(degrees * 3.14159265358979323846 / 180.0);
  std::size_t on = 0;
  for (const DetectedPlane& p : planes.planes)
    for (const Eigen::Vector3d& n : normals)
      if (p.plane.normal.dot(n) >= min_cos) {
        on += p.inliers.size();
        break;
      }
  return on;
}

std::vector<std::uint32_t> points_off_faces(const PointList& cloud,
                                            const std::vector<const DetectedPlane*>& faces,
                                            double band) {
  std::vector<char> on_face(cloud.size(), 0);
  for (const DetectedPlane* f : faces)
    for (std::uint32_t i : f->inliers) on_face[i] = 1;
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (on_face[i]) continue;
    bool near = false;
    for (const DetectedPlane* f : faces)
      near = near || std::abs(f->plane.signed_distance(cloud[i])) < band;
    if (!near) out.push_back(static_cast<std::uint32_t>(i));
  }
  return out;
}

std::optional<ConicalSide> fit_conical_side(const SolveInput& in, const DetectedPlane& base,
                                            const std::vector<const DetectedPlane*>& flat) {
  // The base's normal points away from the cloud, the side lies the other way.
  const Eigen::Vector3d axis = -base.plane.normal;

  Point base_centroid = Point::Zero();
  for (std::uint32_t i : base.inliers) base_centroid += in.cloud[i];
  base_centroid /= static_cast<double>(std::max<std::size_t>(1, base.inliers.size()));
  const auto& rim = base.boundary.size() >= 6 ? base.boundary : base.inliers;
  const auto circle = geometry::fit_circle_in_plane(in.cloud, rim, base_centroid, axis);
  const Point start = circle ? circle->center : base_centroid;

  // Along the side, the distance to the axis changes linearly with the height above the
  // base: r = R - k h. Gauss-Newton over the axis position (s, t in the base plane), R and
  // k uses every side point; the rim circle only gives the start.
  const auto side = points_off_faces(in.cloud, flat, in.cfg.cap_band * in.resolution);
  if (side.size() < 10) return std::nullopt;
  double h_max = 0.0;
  for (std::uint32_t i : side) h_max = std::max(h_max, (in.cloud[i] - start).dot(axis));
  if (!(h_max > 0.0)) return std::nullopt;
  std::vector<std::uint32_t> used;
  for (std::uint32_t i : side) {
    const double h = (in.cloud[i] - start).dot(axis);
    if (h > 0.05 * h_max && h < 0.95 * h_max) used.push_back(i);
  }
  if (used.size() < 10) return std::nullopt;
  const Eigen::Matrix3d frame = frame_from_axis(axis);
  const Eigen::Vector3d u = frame.row(1).transpose(), v = frame.row(2).transpose();
  ConicalSide out;
  out.axis = axis;
  out.centre = start;
  out.top = h_max;
  {
    Eigen::Matrix2d ata = Eigen::Matrix2d::Zero();
    Eigen::Vector2d atb = Eigen::Vector2d::Zero();
    for (std::uint32_t i : used) {
      const Eigen::Vector3d d = in.cloud[i] - out.centre;
      const double h = d.dot(axis);
      const Eigen::Vector2d row(1.0, -h);
      ata.noalias() += row * row.transpose();
      atb.noalias() += row * (d - h * axis).norm();
    }
    const Eigen::Vector2d sol = ata.ldlt().solve(atb);
    out.radius = sol(0);
    out.slope = sol(1);
  }
  for (int it = 0; it < 10; ++it) {
    Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
    Eigen::Vector4d jtr = Eigen::Vector4d::Zero();
    for (std::uint32_t i : used) {
      const Eigen::Vector3d d = in.cloud[i] - out.centre;
      const double h = d.dot(axis);
      const Eigen::Vector3d w = d - h * axis;
      const double r = w.norm();
      if (r < 1e-12) continue;
      const Eigen::Vector4d j(-w.dot(u) / r, -w.dot(v) / r, -1.0, h);
      const double e = r - (out.radius - out.slope * h);
      jtj.noalias() += j * j.transpose();
      jtr.noalias() += j * e;
    }
    const Eigen::Vector4d step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) return std::nullopt;
    out.centre += step(0) * u + step(1) * v;
    out.radius += step(2);
    out.slope += step(3);
    if (step.norm() < 1e-12 * (out.radius + 1.0)) break;
  }
  return out;
}

double explained_share(const SolveInput& in, const FittedSolid& solid) {
  const std::size_t step = std::max<std::size_t>(1, in.cloud.size() / 2000);
  std::size_t n = 0, near = 0;
  for (std::size_t i = 0; i < in.cloud.size(); i += step, ++n)
    near += std::abs(solid.signed_distance(in.cloud[i])) <= in.cfg.inlier_distance * in.resolution;
  return n > 0 ? static_cast<double>(near) / static_cast<double>(n) : 0.0;
}

double stray_face_share(const std::vector<const DetectedPlane*>& faces,
                        const std::vector<Eigen::Vector3d>& directions, double cos_along) {
  std::size_t all = 0, stray = 0;
  for (const DetectedPlane* f : faces) {
    all += f->inliers.size();
    bool along = false;
    for (const Eigen::Vector3d& d : directions) along = along || f->plane.normal.dot(d) >= cos_along;
    if (!along) stray += f->inliers.size();
  }
  return all ? static_cast<double>(stray) / static_cast<double>(all) : 0.0;
}

}  // namespace detail
}  // namespace cloudshape::pipeline
