// Synthetic conditions of the accuracy benchmark: clean, noisy, single view, several objects.
// Cloud i of a shape uses the same solid and point count in clean/noise/outliers/single_view.
#include "accuracy_suites.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>

#include "accuracy_real.hpp"
#include "view_faces.hpp"
#include "synth/mesh_sampling.hpp"
#include "synth/mesh_solids.hpp"
#include "synth/mesh_visibility.hpp"
#include "synth/visibility.hpp"
#include "synth/negative_solid.hpp"
#include "synth/pose.hpp"
#include "synth/prism_section.hpp"
#include "geometry/polygon.hpp"
#include "synth/random_solid.hpp"
#include "synth/resting_pose.hpp"
#include "synth/sample_solid.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape::bench {

namespace {

using synth::ShapeKind;
using synth::SolidSpec;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinPoints = 2000.0;
constexpr double kMaxPoints = 200000.0;
constexpr std::size_t kNewShapeKinds = 3;  // frustum, prism, tetrahedron (the shape index of their streams)

std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Independent streams per purpose, shape and cloud, so adding a condition moves no other cloud.
std::uint64_t stream(std::uint64_t seed, std::uint64_t purpose, std::uint64_t shape,
                     std::uint64_t index) {
  return splitmix(splitmix(splitmix(seed ^ purpose) ^ shape) ^ index);
}

double log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(rng));
}

std::size_t random_point_count(std::mt19937_64& rng, std::size_t cap) {
  const auto drawn = static_cast<std::size_t>(std::lround(log_uniform(rng, kMinPoints, kMaxPoints)));
  return std::min(drawn, cap);
}

// Box axes whose dimension ties another within 3% are undefined up to a swap: not compared.
std::vector<AxisCheck> axis_checks(const std::string& shape,
                                   const std::vector<std::pair<std::string, double>>& dims) {
  if (shape == "cylinder" || shape == "pentagonal_prism") return {{0, false}};
  if (shape == "cone") return {{0, true}};
  std::vector<AxisCheck> checks;
  if (shape != "box") return checks;
  for (int i = 0; i < 3; ++i) {
    bool tie = false;
    for (int j = 0; j < 3; ++j) {
      const double a = dims[i].second, b = dims[j].second;
      tie = tie || (i != j && std::abs(a - b) <= 0.03 * std::max(a, b));
    }
    if (!tie) checks.push_back({i, false});
  }
  return checks;
}

Truth truth_of(const SolidSpec& spec) {
  Truth t;
  t.shape = synth::to_string(spec.kind);
  t.dimensions = spec.dimensions;
  t.center = spec.pose.center;
  t.axes = spec.pose.axes;
  t.size = synth::characteristic_size(spec);
  t.axis_checks = axis_checks(t.shape, t.dimensions);
  return t;
}

struct Drawn {
  SolidSpec spec;
  std::size_t points = 0;
};

Drawn draw_solid(std::size_t shape, std::size_t i, const SuiteOptions& o) {
  std::mt19937_64 rng(stream(o.seed, 1, shape, i));
  Drawn d;
  d.spec = synth::random_solid(synth::all_shape_kinds()[shape], rng, o.solid_size);
  d.points = random_point_count(rng, o.max_points);
  return d;
}

std::pair<double, double> extent_along(const PointList& points, const Eigen::Vector3d& axis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& p : points) {
    const double s = p.dot(axis);
    lo = std::min(lo, s), hi = std::max(hi, s);
  }
  return {lo, hi};
}

// The truth of a single view: what the kept points show. Box: the three extents along its
// axes, re-sorted (axes permuted with them); cylinder, prism: the extent along the axis as
// height. Cone: a fit of its side always finds the apex, so its height runs from the apex
// down to the lowest point seen, and its radius is the cone's radius there (the true ones
// when the base is seen). Radius, side and edge stay true otherwise: a fit recovers them
// from part of the surface.
Truth shown_truth(const SolidSpec& spec, const PointList& kept) {
  Truth t = truth_of(spec);
  if (kept.empty()) return t;
  if (spec.kind == ShapeKind::box) {
    std::vector<std::pair<double, int>> ext;
    for (int k = 0; k < 3; ++k) {
      const auto [lo, hi] = extent_along(kept, spec.pose.axes.row(k).transpose());
      ext.emplace_back(hi - lo, k);
    }
    std::stable_sort(ext.begin(), ext.end(), [](auto a, auto b) { return a.first > b.first; });
    for (int i = 0; i < 3; ++i) {
      t.dimensions[i].second = ext[i].first;
      t.axes.row(i) = spec.pose.axes.row(ext[i].second);
    }
    t.axis_checks = axis_checks(t.shape, t.dimensions);
  } else if (spec.kind == ShapeKind::cone) {
    const double h = synth::dimension(spec, "height");
    const auto [lo, hi] = extent_along(kept, spec.pose.axes.row(0).transpose());
    const double shown = std::clamp(spec.pose.center.dot(spec.pose.axes.row(0)) + h - lo, 0.0, h);
    for (auto& [name, value] : t.dimensions) value *= shown / h;  // radius and height alike
    (void)hi;
  } else if (spec.kind == ShapeKind::cylinder || spec.kind == ShapeKind::pentagonal_prism) {
    const auto [lo, hi] = extent_along(kept, spec.pose.axes.row(0).transpose());
    for (auto& [name, value] : t.dimensions)
      if (name == "height") value = hi - lo;
  }
  return t;
}

// Camera 3 sizes from the centre; then the "table": every point within the lowest 2% of the
// solid's world-z range is dropped. single_view: the solid in its random pose (often balanced
// on an edge or corner), the camera uniform over the upper hemisphere of world z. table_view:
// the solid lies at rest on a face, cap or side (place_at_rest), the camera looks down at it
// from 15-75 degrees above the table, as a camera over a table does.
TestCloud single_view_cloud(Drawn d, std::uint64_t cloud_seed, double size, bool at_rest) {
  std::mt19937_64 rng(cloud_seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (at_rest) synth::place_at_rest(d.spec, rng);
  const double z = at_rest ? std::sin((15.0 + 60.0 * u(rng)) * kPi / 180.0) : u(rng);
  const double phi = 2.0 * kPi * u(rng), r = std::sqrt(1.0 - z * z);
  synth::CloudOptions options;
  options.points = d.points;
  options.view =
      d.spec.pose.center + 3.0 * size * Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z);
  PointList points = synth::make_synthetic_cloud({d.spec}, options, rng()).points;

  const PointList whole = synth::sample_solid_surface(d.spec, 4000, rng);
  const auto [zlo, zhi] = extent_along(whole, Eigen::Vector3d::UnitZ());
  const double table = zlo + 0.02 * (zhi - zlo);
  points.erase(
      std::remove_if(points.begin(), points.end(), [&](const Point& p) { return p.z() < table; }),
      points.end());
  TestCloud cloud;
  cloud.truths.push_back(shown_truth(d.spec, points));
  // Where the camera looks from, relative to the solid: the angle between its local axes[0]
  // (a cone's base-to-apex direction) and the direction to the camera, and between world up.
  const Eigen::Vector3d to_camera = (*options.view - d.spec.pose.center).normalized();
  char note[96];
  std::snprintf(note, sizeof note, "view_to_axis0=%.0fdeg axis0_to_up=%.0fdeg",
                std::acos(std::clamp(to_camera.dot(d.spec.pose.axes.row(0)), -1.0, 1.0)) * 180 / kPi,
                std::acos(std::clamp(d.spec.pose.axes(0, 2), -1.0, 1.0)) * 180 / kPi);
  cloud.note = note;
  if (d.spec.kind == ShapeKind::cone) {
    // How much of the visible cloud is lateral surface rather than base disc.
    std::size_t lateral = 0;
    for (const auto& p : points)
      lateral += (p - d.spec.pose.center).dot(d.spec.pose.axes.row(0)) > 0.01 * size ? 1 : 0;
    std::snprintf(note, sizeof note, " lateral=%.1f%% true_height=%.4g", 
                  100.0 * lateral / std::max<std::size_t>(points.size(), 1),
                  d.spec.dimensions[1].second);
    cloud.note += note;
  }
  cloud.points = std::move(points);
  return cloud;
}

double bounding_radius(const SolidSpec& spec, std::mt19937_64& rng) {
  double r = 0.0;
  for (const auto& p : synth::sample_solid_surface(spec, 2000, rng))
    r = std::max(r, (p - spec.pose.center).norm());
  return r;
}

// 2-4 solids, the first of the row's shape, the others of any shape; centres are re-drawn
// until every two bounding spheres are more than one solid size apart.
TestCloud multi_object_cloud(std::size_t shape, std::uint64_t cloud_seed, double size,
                             std::size_t max_points) {
  std::mt19937_64 rng(cloud_seed);
  const auto& kinds = synth::all_shape_kinds();
  const int n = std::uniform_int_distribution<int>(2, 4)(rng);
  std::uniform_int_distribution<std::size_t> any_kind(0, kinds.size() - 1);
  std::vector<SolidSpec> solids;
  std::vector<double> radii;
  double box = 2.5 * size * n;  // the cube the centres are drawn in; grows if too crowded
  for (int k = 0; k < n; ++k) {
    SolidSpec s = synth::random_solid(kinds[k == 0 ? shape : any_kind(rng)], rng, size);
    const double radius = bounding_radius(s, rng);
    for (int attempt = 0;; ++attempt) {
      if (attempt > 0 && attempt % 200 == 0) box *= 1.2;
      std::uniform_real_distribution<double> u(-0.5 * box, 0.5 * box);
      s.pose.center = Eigen::Vector3d(u(rng), u(rng), u(rng));
      bool apart = true;
      for (std::size_t j = 0; j < solids.size() && apart; ++j)
        apart = (s.pose.center - solids[j].pose.center).norm() > radius + radii[j] + size;
      if (apart) break;
    }
    solids.push_back(s);
    radii.push_back(radius);
  }
  synth::CloudOptions options;
  options.points = random_point_count(rng, max_points);
  TestCloud cloud;
  cloud.points = synth::make_synthetic_cloud(solids, options, rng()).points;
  for (const auto& s : solids) cloud.truths.push_back(truth_of(s));
  cloud.gate_matching = true;
  return cloud;
}

// The whole surface of a mesh solid, noise sigma 0.5% of its size.
PointList noisy_mesh_points(const synth::SolidMesh& mesh, std::mt19937_64& rng, const SuiteOptions& o) {
  PointList points =
      synth::sample_mesh_surface(mesh.vertices, mesh.triangles, random_point_count(rng, o.max_points), rng);
  std::normal_distribution<double> noise(0.0, 0.005 * mesh.size);
  for (Point& p : points) p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  return points;
}

// new_shapes: the whole surface; new_shapes_view: what a camera 3 sizes from the centre, in a
// direction uniform over the sphere, sees (exact ray casting on the mesh). Noise 0.5% of size.
// `faces_of` classifies the view's noise-free points by face (which decides whether the view
// determines the solid); it draws nothing from rng, so the clouds are those of before.
PointList new_shape_points(const synth::SolidMesh& mesh, std::mt19937_64& rng, const SuiteOptions& o, bool view,
                           const std::function<void(const PointList&)>& faces_of) {
  if (!view) return noisy_mesh_points(mesh, rng, o);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const Eigen::Vector3d dir = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
  const Eigen::Vector3d camera = mesh.center + 3.0 * mesh.size * dir;
  const synth::MeshVisibility visibility(mesh.vertices, mesh.triangles);
  PointList points = synth::sample_visible(
      [&](std::size_t m) { return synth::sample_mesh_surface(mesh.vertices, mesh.triangles, m, rng); },
      [&](const PointList& c) { return visibility.visible(c, camera); }, random_point_count(rng, o.max_points), rng);
  faces_of(points);
  std::normal_distribution<double> noise(0.0, 0.005 * mesh.size);
  for (Point& p : points) p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  return points;
}

// A solid outside the vocabulary, its whole surface, noise sigma 0.5% of its size. Its truth
// is `unknown`, labelled with its kind; it has no pose to score.
TestCloud negative_cloud(std::size_t kind, std::size_t i, std::uint64_t cloud_seed, const SuiteOptions& o) {
  std::mt19937_64 rng(cloud_seed);
  const synth::NegativeKind k = synth::all_negative_kinds()[kind];
  const synth::SolidMesh mesh = synth::random_negative_solid(k, rng, o.solid_size);
  TestCloud cloud;
  cloud.points = noisy_mesh_points(mesh, rng, o);
  Truth t;
  t.shape = "unknown";
  t.label = synth::to_string(k);
  t.center = mesh.center;
  t.size = mesh.size;
  t.has_pose = false;
  cloud.truths.push_back(t);
  cloud.source = "negatives-" + t.label + "-" + std::to_string(i);
  cloud.note = t.label;
  return cloud;
}

// A view that does not determine its solid is tallied in the shape's undetermined row.
void record_view(const ViewFaces& faces, Truth& truth, std::string& note) {
  if (!faces.determines) truth.row = undetermined_row(truth.shape);
  note += (note.empty() ? "" : " ") + faces.note;
}

// The shapes beyond the six (a frustum: radius and height log-uniform within 1:4, the top 25-80%
// of the base), whole surface, noise sigma 0.5% of size.
TestCloud frustum_cloud(std::size_t i, std::uint64_t cloud_seed, const SuiteOptions& o, bool view) {
  std::mt19937_64 rng(cloud_seed);
  const double height_over_radius = log_uniform(rng, 0.5, 4.0);
  const double radius = o.solid_size / std::max(2.0, height_over_radius);
  const double top = radius * std::uniform_real_distribution<double>(0.25, 0.8)(rng);
  const synth::Pose pose = synth::random_pose(rng, o.solid_size);
  const synth::SolidMesh mesh = synth::frustum_mesh(radius, top, radius * height_over_radius, pose);
  TestCloud cloud;
  ViewFaces faces;
  cloud.points = new_shape_points(mesh, rng, o, view, [&](const PointList& p) {
    faces = frustum_view_faces(p, radius * height_over_radius, pose);
  });
  Truth t;
  t.shape = "frustum";
  t.dimensions = {{"radius", radius}, {"top_radius", top}, {"height", radius * height_over_radius}};
  t.center = pose.center;
  t.axes = pose.axes;
  t.size = mesh.size;
  t.axis_checks = {{0, true}};
  if (view) record_view(faces, t, cloud.note);
  cloud.truths.push_back(t);
  cloud.source = "new_shapes-frustum-" + std::to_string(i);
  return cloud;
}

// A right prism: the cross-section kinds in turn (triangle, rhombus, regular and irregular
// hexagon, convex n-gon, L, T, plus, star), height over width log-uniform within 1:3..3:1.
TestCloud prism_cloud(std::size_t i, std::uint64_t cloud_seed, const SuiteOptions& o, bool view) {
  std::mt19937_64 rng(cloud_seed);
  const auto& kinds = synth::all_section_kinds();
  const synth::PrismSection section = synth::random_section(kinds[i % kinds.size()], rng);
  const double height_over_width = log_uniform(rng, 1.0 / 3.0, 3.0);
  const double width = o.solid_size / std::max(1.0, height_over_width);
  geometry::Polygon2 polygon = section.polygon;
  for (auto& p : polygon) p *= width;
  const synth::Pose pose = synth::random_pose(rng, o.solid_size);
  const synth::SolidMesh mesh = synth::prism_mesh(polygon, width * height_over_width, pose);
  TestCloud cloud;
  ViewFaces faces;
  cloud.points = new_shape_points(mesh, rng, o, view, [&](const PointList& p) {
    faces = prism_view_faces(p, polygon, width * height_over_width, pose);
  });
  Truth t;
  t.shape = "prism";
  t.label = synth::to_string(section.kind);
  t.dimensions = {{"height", width * height_over_width}, {"sides", static_cast<double>(polygon.size())}};
  if (section.regular) t.dimensions.emplace_back("side", geometry::perimeter(polygon) / polygon.size());
  t.polygon = polygon;
  t.center = pose.center;
  t.axes = pose.axes;
  t.size = mesh.size;
  t.axis_checks = {{0, false}};
  cloud.note = t.label;
  if (view) record_view(faces, t, cloud.note);
  cloud.truths.push_back(t);
  cloud.source = "new_shapes-prism-" + t.label + "-" + std::to_string(i);
  return cloud;
}

// Any tetrahedron: four corners uniform in a ball, kept when no edge is under 40% of the longest
// and the volume is at least 30% of a regular one's with that edge (no sliver, no needle).
TestCloud tetrahedron_cloud(std::size_t i, std::uint64_t cloud_seed, const SuiteOptions& o, bool view) {
  std::mt19937_64 rng(cloud_seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<Eigen::Vector3d, 4> c;
  double longest = 0.0, shortest = 0.0, mean = 0.0;
  for (;;) {
    for (auto& v : c) {
      do v = Eigen::Vector3d(u(rng), u(rng), u(rng));
      while (v.norm() > 1.0);
    }
    longest = 0.0, shortest = 1e9, mean = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double e = (c[a] - c[b]).norm();
        longest = std::max(longest, e), shortest = std::min(shortest, e), mean += e / 6.0;
      }
    const double volume = std::abs((c[1] - c[0]).dot((c[2] - c[0]).cross(c[3] - c[0]))) / 6.0;
    const double regular_volume = longest * longest * longest / (6.0 * std::sqrt(2.0));
    if (shortest >= 0.4 * longest && volume >= 0.3 * regular_volume) break;
  }
  const synth::Pose pose = synth::random_pose(rng, o.solid_size);
  for (auto& v : c) v = pose.center + (o.solid_size / longest) * v;
  const synth::SolidMesh mesh = synth::tetrahedron_mesh(c);
  TestCloud cloud;
  ViewFaces faces;
  cloud.points = new_shape_points(mesh, rng, o, view, [&](const PointList& p) { faces = tetrahedron_view_faces(p, c); });
  Truth t;
  t.shape = "tetrahedron";
  t.label = "irregular";
  t.dimensions = {{"edge", mean * o.solid_size / longest}};
  t.center = mesh.center;
  t.size = mesh.size;
  cloud.note = "irregular";
  if (view) record_view(faces, t, cloud.note);
  cloud.truths.push_back(t);
  cloud.source = "new_shapes-tetrahedron-" + std::to_string(i);
  return cloud;
}

TestCloud new_shape_cloud(std::size_t kind, std::size_t i, std::uint64_t cloud_seed, const SuiteOptions& o,
                          bool view) {
  TestCloud cloud = kind == 1 ? prism_cloud(i, cloud_seed, o, view)
                    : kind == 2 ? tetrahedron_cloud(i, cloud_seed, o, view)
                                : frustum_cloud(i, cloud_seed, o, view);
  if (view) cloud.source.replace(0, std::string("new_shapes").size(), "new_shapes_view");
  return cloud;
}

}  // namespace

const std::vector<std::string>& accuracy_conditions() {
  static const std::vector<std::string> names = {
      "clean", "noise", "outliers", "density", "single_view", "table_view", "multi", "real", "negatives",
      "new_shapes", "new_shapes_view"};
  return names;
}

std::string describe_condition(const std::string& c) {
  if (c == "clean") return "complete surface, no noise";
  if (c == "noise") return "complete surface, Gaussian noise sigma 0.5% of size";
  if (c == "outliers") return "complete surface, noise sigma 1% of size + 3% outliers";
  if (c == "single_view")
    return "one camera 3 sizes away, uniform over the upper hemisphere; points in the lowest "
           "2% of the solid's z range dropped (table); truth = extents shown";
  if (c == "density")
    return "complete surface; density falls with the squared distance from a point 3 sizes "
           "away (random direction), and 6 patches lose up to 80% of their points";
  if (c == "table_view")
    return "the solid at rest on a face, cap or side (random), camera 3 sizes away, 15-75 deg "
           "above the table, any azimuth; lowest 2% of z dropped (table); truth = extents shown";
  if (c == "multi")
    return "2-4 solids >1 size apart, the first of the row's shape; match by centre within 0.5 "
           "size (an unknown result has no centre: missed + false)";
  if (c == "real") return "YCB + ravens meshes, 20k points, seed 1; no pose truth";
  if (c == "negatives")
    return "solids none of the shapes (ellipsoid, torus, square pyramid, octahedron, capsule), "
           "whole, "
           "noise sigma 0.5% of size; right = unknown";
  if (c == "new_shapes")
    return "shapes beyond the six (frustum; prism: triangle, rhombus, hexagons, convex n-gon, L, T, plus, "
           "star; any tetrahedron), complete surface, noise sigma 0.5% of size; a prism is right with "
           "its sides, its dimensions: height, sqrt(area), perimeter";
  if (c == "new_shapes_view")
    return "the new shapes of new_shapes, each seen by one camera 3 sizes away (any direction, exact "
           "ray casting), noise sigma 0.5% of size; truth = the whole solid. Scored apart (rows /undet, not in "
           "all): views that do not determine the solid (a face holds >= 5% of the points to count as seen; a "
           "prism needs a cap and a side, a tetrahedron two faces, a frustum its side); right there = the "
           "shape, honest = unknown";
  return {};
}

std::size_t suite_size(const std::string& condition, const SuiteOptions& o) {
  if (condition == "real") return present_real_samples(o.shared_data_dir).size();
  if (condition == "negatives")
    return static_cast<std::size_t>(std::max(o.count, 0)) * synth::all_negative_kinds().size();
  if (condition == "new_shapes" || condition == "new_shapes_view")
    return static_cast<std::size_t>(std::max(o.count, 0)) * kNewShapeKinds;
  return static_cast<std::size_t>(std::max(o.count, 0)) * synth::all_shape_kinds().size();
}

TestCloud make_test_cloud(const std::string& condition, std::size_t index, const SuiteOptions& o) {
  if (condition == "real")
    return make_real_cloud(present_real_samples(o.shared_data_dir).at(index), o.shared_data_dir);
  const std::size_t shape = index / static_cast<std::size_t>(o.count);
  const std::size_t i = index % static_cast<std::size_t>(o.count);
  // Stream ids in the order the conditions were added, not the report's, so a new condition
  // moves no existing cloud.
  static const std::vector<std::string> stream_order = {
      "clean", "noise", "outliers", "single_view", "multi", "real", "table_view", "density", "negatives",
      "new_shapes", "new_shapes_view"};
  const auto pos = std::find(stream_order.begin(), stream_order.end(), condition);
  if (pos == stream_order.end()) throw std::invalid_argument("unknown condition '" + condition + "'");
  const std::uint64_t cloud_seed = stream(o.seed, 2 + (pos - stream_order.begin()), shape, i);
  if (condition == "negatives") return negative_cloud(shape, i, cloud_seed, o);
  if (condition == "new_shapes" || condition == "new_shapes_view")
    return new_shape_cloud(shape, i, cloud_seed, o, condition == "new_shapes_view");
  const std::string source =
      condition + "-" + synth::to_string(synth::all_shape_kinds()[shape]) + "-" + std::to_string(i);

  TestCloud cloud;
  if (condition == "multi") {
    cloud = multi_object_cloud(shape, cloud_seed, o.solid_size, o.max_points);
  } else {
    const Drawn d = draw_solid(shape, i, o);
    if (condition == "single_view" || condition == "table_view") {
      cloud = single_view_cloud(d, cloud_seed, o.solid_size, condition == "table_view");
    } else {
      const double size = synth::characteristic_size(d.spec);
      synth::CloudOptions options;
      options.points = d.points;
      options.noise_sigma = condition == "noise"      ? 0.005 * size
                            : condition == "outliers" ? 0.01 * size
                                                      : 0.0;
      options.outlier_fraction = condition == "outliers" ? 0.03 : 0.0;
      if (condition == "density") {
        std::mt19937_64 rng(cloud_seed ^ 0xde);
        std::normal_distribution<double> gauss(0.0, 1.0);
        const Eigen::Vector3d dir = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
        options.density.falloff_from = d.spec.pose.center + 3.0 * o.solid_size * dir;
        options.density.patchiness = 0.8;
      }
      cloud.points = synth::make_synthetic_cloud({d.spec}, options, cloud_seed).points;
      cloud.truths.push_back(truth_of(d.spec));
    }
  }
  cloud.source = source;
  return cloud;
}

}  // namespace cloudshape::bench
