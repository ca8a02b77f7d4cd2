#include "pipeline/classify.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/circle.hpp"
#include "geometry/pca.hpp"

namespace cloudshape::pipeline {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Angular gap around `tip` of the neighbourhood (thesis 3.2.3): 180 deg for an edge (the
// projected neighbourhood is a half-plane), more for a corner (a wedge). Measured in 3-D
// around the inward axis from the tip to the centroid, because at sharp corners
// lambda0 ~ lambda1 and the thesis' e1 projection plane is arbitrary. Only the outer ring
// counts: the nearest neighbours' directions mostly show the sampling offset.
double wedge_gap(const PointList& cloud, const std::vector<std::uint32_t>& neighbourhood,
                 std::uint32_t tip, const Point& centroid, double inner_exclusion) {
  const Point& k = cloud[tip];
  const Eigen::Vector3d inward = centroid - k;
  if (!(inward.norm() > 0.0)) return kPi;
  const Eigen::Vector3d axis = inward.normalized();
  double reach = 0.0;
  for (std::uint32_t j : neighbourhood) reach = std::max(reach, (cloud[j] - k).norm());
  double widest = 0.0;
  for (std::uint32_t j : neighbourhood) {
    const Eigen::Vector3d d = cloud[j] - k;
    const double len = d.norm();
    if (j == tip || len < inner_exclusion * reach) continue;
    widest = std::max(widest, std::acos(std::clamp(d.dot(axis) / len, -1.0, 1.0)));
  }
  return 2.0 * kPi - 2.0 * widest;
}

void add_unique(std::vector<Shape>& list, Shape s) {
  if (s != Shape::unknown && std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
}

// The solids the flat faces point to: polyhedra when faces cover the cloud, solids of
// revolution otherwise (their caps and bases are the only true faces they have).
std::vector<Shape> shapes_from_faces(const PlaneSegmentation& planes, double face_fraction,
                                     const config::ClassifyConfig& cfg) {
  std::vector<const DetectedPlane*> faces;
  for (const auto& p : planes.planes)
    if (p.is_face) faces.push_back(&p);
  std::vector<Shape> out;
  if (face_fraction >= cfg.polyhedron_face_fraction) {
    if (faces.size() <= 4) out = {Shape::tetrahedron, Shape::box, Shape::pentagonal_prism};
    else if (faces.size() <= 6) out = {Shape::box, Shape::pentagonal_prism, Shape::tetrahedron};
    else out = {Shape::pentagonal_prism, Shape::box, Shape::tetrahedron};
    return out;
  }
  bool parallel_pair = false;
  for (std::size_t a = 0; a < faces.size(); ++a)
    for (std::size_t b = a + 1; b < faces.size(); ++b)
      if (faces[a]->plane.normal.dot(faces[b]->plane.normal) < -0.95) parallel_pair = true;
  // A frustum comes last: it is the answer only where a cylinder and a cone both fall short.
  if (faces.empty()) out = {Shape::sphere, Shape::cylinder, Shape::cone, Shape::frustum};
  else if (parallel_pair) out = {Shape::cylinder, Shape::cone, Shape::frustum};
  else out = {Shape::cone, Shape::cylinder, Shape::frustum};
  return out;
}

// Reads the outline of every face large enough to have one worth reading.
void read_outlines(const PointList& cloud, const PlaneSegmentation& planes,
                   const config::ClassifyConfig& cfg, Classification& out) {
  std::optional<std::size_t> circle;
  FaceOutline circle_outline;
  bool rectangle = false;
  const double min_points = cfg.outline_min_share * static_cast<double>(cloud.size());
  for (std::size_t k = 0; k < planes.planes.size(); ++k) {
    const DetectedPlane& p = planes.planes[k];
    if (!p.is_face || static_cast<double>(p.inliers.size()) < min_points) continue;
    const FaceOutline o = face_outline(cloud, p, cfg.outline_circle_rms, cfg.outline_circle_harmonic, cfg.outline_rect_fill);
    if (o.kind == OutlineKind::rectangle) rectangle = true;
    if (o.kind == OutlineKind::circle &&
        (!circle || p.inliers.size() > planes.planes[*circle].inliers.size())) {
      circle = k;
      circle_outline = o;
    }
  }
  if (circle && rectangle) return;
  out.rectangular_face = rectangle;
  out.cap_plane = circle;
  out.cap_outline = circle_outline;
}

}  // namespace

TypedKeypoint type_keypoint(const PointList& cloud, const Keypoint& keypoint,
                            const config::ClassifyConfig& cfg) {
  TypedKeypoint out;
  out.index = keypoint.index;
  const geometry::Pca pca = geometry::compute_pca(cloud, keypoint.neighbourhood);
  out.curvature = pca.surface_variation();
  if (out.curvature < cfg.border_curvature) {
    out.type = KeypointType::border;
    return out;
  }
  // The key-point is the sample that pursuit reached, often a resolution or two short of
  // the true vertex; its nearest neighbours are tried as the wedge's tip as well and the
  // widest gap counts, so a vertex is not missed because no sample sits exactly on it.
  const auto tips = std::min<std::size_t>(keypoint.neighbourhood.size(),
                                          static_cast<std::size_t>(std::max<std::int64_t>(1, cfg.apex_candidates)));
  double gap = 0.0;
  for (std::size_t t = 0; t < tips; ++t) {
    const std::uint32_t tip = keypoint.neighbourhood[t];
    gap = std::max(gap, wedge_gap(cloud, keypoint.neighbourhood, tip, pca.centroid, cfg.inner_exclusion));
  }
  out.gap_degrees = gap * 180.0 / kPi;
  out.type = out.gap_degrees > cfg.corner_gap_degrees ? KeypointType::corner : KeypointType::edge;
  return out;
}

Shape shape_from_keypoints(const KeypointCounts& counts) {
  switch (counts.corner) {
    case 0: return counts.edge + counts.border > 0 ? Shape::cylinder : Shape::unknown;
    case 1: return Shape::cone;
    case 4: return Shape::tetrahedron;
    case 8: return Shape::box;
    case 10: return Shape::pentagonal_prism;
    default: return Shape::unknown;
  }
}

Classification classify_cloud(const PointList& cloud, const PlaneSegmentation& planes,
                              const KeypointSet& keypoints, double resolution,
                              const config::ClassifyConfig& cfg) {
  Classification out;
  if (cloud.size() < static_cast<std::size_t>(std::max<std::int64_t>(4, cfg.min_points))) {
    out.reason = "too few points (" + std::to_string(cloud.size()) + " after filtering)";
    return out;
  }
  const geometry::Pca pca = geometry::compute_pca(cloud);
  const double thin = cfg.degenerate_thickness * resolution;
  if (!(resolution > 0.0) || std::sqrt(pca.eigenvalues[2]) <= 0.0) {
    out.reason = "all points coincide";
    return out;
  }
  if (std::sqrt(pca.eigenvalues[1]) < thin) {
    out.reason = "all points collinear";
    return out;
  }
  if (std::sqrt(pca.eigenvalues[0]) < thin) {
    out.reason = "all points coplanar";
    return out;
  }

  for (const Keypoint& kp : keypoints.keypoints) {
    out.keypoints.push_back(type_keypoint(cloud, kp, cfg));
    switch (out.keypoints.back().type) {
      case KeypointType::corner: ++out.counts.corner; break;
      case KeypointType::edge: ++out.counts.edge; break;
      case KeypointType::border: ++out.counts.border; break;
    }
  }
  std::size_t on_faces = 0;
  for (const auto& p : planes.planes)
    if (p.is_face) on_faces += p.inliers.size();
  out.face_fraction = static_cast<double>(on_faces) / static_cast<double>(cloud.size());

  read_outlines(cloud, planes, cfg, out);
  // Sphere test (thesis 3.3.4), on a geometric fit rather than the centroid distance so
  // that a partial sphere passes too. A sphere has no flat face: with too many points on
  // faces, or a circular or rectangular one, the test fails whatever the fit (not made).
  if (out.face_fraction <= cfg.sphere_max_face_fraction && !out.cap_plane && !out.rectangular_face) {
    std::vector<std::uint32_t> sample;
    const std::size_t step = std::max<std::size_t>(1, cloud.size() / 3000);
    for (std::size_t i = 0; i < cloud.size(); i += step) sample.push_back(static_cast<std::uint32_t>(i));
    if (const auto sphere = geometry::fit_sphere(cloud, sample)) {
      out.sphere_test = sphere->rms < cfg.sphere_max_rms * sphere->radius;
    }
  }
  out.shape = out.sphere_test ? Shape::sphere : shape_from_keypoints(out.counts);
  if (out.cap_plane) {
    // A circular face: a can's lid, a cup's bottom; of the solids only these have one.
    out.shape = Shape::cylinder;
    // A regular polygon's cap reads as a circle too (a hexagonal nut): the prism stays in.
    out.candidates = {Shape::cylinder, Shape::cone, Shape::frustum, Shape::prism};
    return out;
  }
  add_unique(out.candidates, out.shape);
  for (Shape s : shapes_from_faces(planes, out.face_fraction, cfg)) add_unique(out.candidates, s);
  for (Shape s : kSolidShapes) add_unique(out.candidates, s);
  // Points a sphere fits (a ball on two or three lidar rings: circles any round solid passes
  // through) are no frustum's: it has one parameter more than a cone and explains them as well.
  if (out.sphere_test)
    out.candidates.erase(std::remove(out.candidates.begin(), out.candidates.end(), Shape::frustum),
                         out.candidates.end());
  if (out.rectangular_face) {
    // No solid of revolution has a rectangular flat face.
    out.candidates.erase(std::remove_if(out.candidates.begin(), out.candidates.end(),
                                        [](Shape s) {
                                          return s == Shape::cylinder || s == Shape::cone ||
                                                 s == Shape::sphere || s == Shape::frustum;
                                        }),
                         out.candidates.end());
    if (out.shape == Shape::cylinder || out.shape == Shape::cone) out.shape = out.candidates.front();
  }
  // Any other prism comes last: the six keep every tie.
  add_unique(out.candidates, Shape::prism);
  return out;
}

}  // namespace cloudshape::pipeline
