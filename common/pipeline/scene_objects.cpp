#include "pipeline/scene_objects.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "geometry/kdtree.hpp"
#include "geometry/pca.hpp"
#include "geometry/plane.hpp"
#include "geometry/voxel_grid.hpp"
#include "pipeline/split_objects.hpp"
#include "pipeline/support_plane.hpp"

namespace cloudshape::pipeline {
namespace {

struct StructuralPlane {
  geometry::Plane plane;
  Eigen::Vector3d u, v;              // in-plane basis
  std::array<double, 4> footprint;  // extents along u and v of the plane's points
};

// Within `band` of the plane and over the part of it that was seen, widened by the band (where
// two walls meet, the points' normals are mixed): the plane of a wall goes on through the rest
// of the scene, the wall does not.
bool on_structure(const StructuralPlane& sp, const Point& p, double band) {
  const double a = p.dot(sp.u), b = p.dot(sp.v);
  return std::abs(sp.plane.signed_distance(p)) < band && a >= sp.footprint[0] - band &&
         a <= sp.footprint[1] + band && b >= sp.footprint[2] - band && b <= sp.footprint[3] + band;
}

struct Structure {
  std::vector<StructuralPlane> planes;
  PointList rest;  // the points on none of them
};

// Local surface normals (k nearest neighbours): a scan ring at the sensor's height lies in a
// plane too, but across walls and objects whose surfaces are not that plane.
std::vector<Eigen::Vector3d> local_normals(const PointList& points, std::size_t k) {
  std::vector<Eigen::Vector3d> normals(points.size(), Eigen::Vector3d::Zero());
  if (points.size() <= k) return normals;
  const geometry::KdTree tree(points);
  std::vector<std::uint32_t> idx;
  for (std::size_t i = 0; i < points.size(); ++i) {
    tree.knn(points[i], k, idx);
    normals[i] = geometry::compute_pca(points, idx).eigenvectors.col(0);
  }
  return normals;
}

// Dominant planes, one after the other, while they are large enough to be the scene's own.
Structure find_structure(const PointList& points, double band, double diagonal,
                         const config::PreprocessConfig& cfg) {
  Structure s;
  s.rest = points;
  std::vector<Eigen::Vector3d> normals = local_normals(points, static_cast<std::size_t>(cfg.structure_normal_neighbours));
  const double min_cos = std::cos(cfg.structure_normal_degrees * 3.14159265358979323846 / 180.0);
  const double min_points = cfg.structure_min_share * static_cast<double>(points.size());
  for (std::int64_t k = 0; k < cfg.structure_max_planes && s.rest.size() >= 3; ++k) {
    const auto plane = dominant_plane(s.rest, band, cfg.support_iterations, cfg.support_score_samples,
                                      59907u + static_cast<std::uint64_t>(k), &normals, min_cos);
    if (!plane) break;
    std::vector<std::uint32_t> on;
    for (std::size_t i = 0; i < s.rest.size(); ++i)
      if (std::abs(plane->signed_distance(s.rest[i])) < band && std::abs(normals[i].dot(plane->normal)) >= min_cos)
        on.push_back(static_cast<std::uint32_t>(i));
    if (static_cast<double>(on.size()) < min_points) break;
    StructuralPlane sp{*plane, {}, {}, {}};
    geometry::plane_basis(plane->normal, sp.u, sp.v);
    sp.footprint = footprint(s.rest, on, sp.u, sp.v);
    const double extent = std::hypot(sp.footprint[1] - sp.footprint[0], sp.footprint[3] - sp.footprint[2]);
    if (extent < cfg.structure_min_extent * diagonal) break;
    // Where two structural planes meet, the points' own normals are mixed: every point within
    // the band over the plane's seen part goes with it.
    PointList off;
    std::vector<Eigen::Vector3d> off_normals;
    for (std::size_t i = 0; i < s.rest.size(); ++i)
      if (!on_structure(sp, s.rest[i], band)) off.push_back(s.rest[i]), off_normals.push_back(normals[i]);
    s.planes.push_back(sp);
    s.rest = std::move(off);
    normals = std::move(off_normals);
  }
  return s;
}

// An object among the structure: small against the scene, and over the middle of a
// structural plane (a solid's own face ends where the solid's other faces do).
bool is_scene_object(const PointList& part, const Structure& s, double diagonal,
                     const config::PreprocessConfig& cfg) {
  if (geometry::bounding_box(part).diagonal() > cfg.scene_object_max_extent * diagonal) return false;
  std::vector<std::uint32_t> all(part.size());
  for (std::size_t i = 0; i < part.size(); ++i) all[i] = static_cast<std::uint32_t>(i);
  return std::any_of(s.planes.begin(), s.planes.end(), [&](const StructuralPlane& sp) {
    return surrounds(sp.footprint, footprint(part, all, sp.u, sp.v), cfg.scene_object_margin);
  });
}

// Thinner than `thickness` (standard deviation along the least principal axis): a piece
// of a plane (a wall's fragment, a strip of a curved solid cut by the band), not an object.
bool is_flat(const PointList& points, double thickness) {
  return std::sqrt(std::max(geometry::compute_pca(points).eigenvalues(0), 0.0)) < thickness;
}

struct CellKeyHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& k) const {
    return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
  }
};

// Raw points of each object: those in or next to (26-neighbourhood) a cell of its points,
// farther than `band` from every structural plane.
std::vector<PointList> raw_points_of(const PointList& raw, const std::vector<PointList>& objects,
                                     const Structure& s, double cell, double band) {
  using Key = std::array<std::int64_t, 3>;
  const auto key_of = [cell](const Point& p) {
    return Key{static_cast<std::int64_t>(std::floor(p.x() / cell)), static_cast<std::int64_t>(std::floor(p.y() / cell)),
               static_cast<std::int64_t>(std::floor(p.z() / cell))};
  };
  std::unordered_map<Key, std::size_t, CellKeyHash> owner;
  for (std::size_t o = 0; o < objects.size(); ++o)
    for (const Point& p : objects[o]) {
      const Key k = key_of(p);
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy)
          for (std::int64_t dz = -1; dz <= 1; ++dz) owner.emplace(Key{k[0] + dx, k[1] + dy, k[2] + dz}, o);
    }
  std::vector<PointList> out(objects.size());
  for (const Point& p : raw) {
    const auto it = owner.find(key_of(p));
    if (it == owner.end()) continue;
    if (std::none_of(s.planes.begin(), s.planes.end(),
                     [&](const StructuralPlane& sp) { return on_structure(sp, p, band); }))
      out[it->second].push_back(p);
  }
  return out;
}

}  // namespace

std::optional<std::vector<ObjectCloud>> scene_objects(const PointList& raw, const PreprocessedCloud& pre,
                                                      const config::PreprocessConfig& cfg) {
  if (!cfg.remove_structure || pre.points.size() < 100 || !(pre.resolution > 0.0)) return std::nullopt;
  const double diagonal = geometry::bounding_box(pre.points).diagonal();
  const double band = cfg.support_band * pre.resolution;
  const double cell = cfg.object_gap * pre.resolution;
  const Structure s = find_structure(pre.points, band, diagonal, cfg);
  // A scene is mostly structure; a cloud of solids, one with a large face, is not.
  if (s.planes.empty() || static_cast<double>(pre.points.size() - s.rest.size()) <
                              cfg.structure_min_total * static_cast<double>(pre.points.size()))
    return std::nullopt;
  std::vector<PointList> parts = connected_components(s.rest, cell);
  parts.erase(std::remove_if(parts.begin(), parts.end(),
                             [&](const PointList& part) { return !is_scene_object(part, s, diagonal, cfg); }),
              parts.end());
  if (parts.empty()) return std::nullopt;
  config::PreprocessConfig own = cfg;
  own.isolated_voxel_neighbours = 0;
  std::vector<ObjectCloud> objects;
  for (const PointList& points : raw_points_of(raw, parts, s, cell, band)) {
    if (static_cast<std::int64_t>(points.size()) < cfg.scene_object_min_points) continue;
    PreprocessedCloud object = preprocess_cloud(points, own);
    if (object.points.size() < 4 || is_flat(object.points, cfg.fragment_max_width * object.resolution)) continue;
    objects.push_back({std::move(object.points), object.resolution});
  }
  if (objects.empty()) return std::nullopt;
  return objects;
}

}  // namespace cloudshape::pipeline
