// Tetrahedra and pentagonal prisms seen from one side (two or three faces) are recognised
// with their dimensions, and single views of the other solids never pass for them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"
#include "synth/pose.hpp"
#include "synth/solid_geometry.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape {
namespace {

using synth::ShapeKind;

// Tolerances on what a single view shows (every visible face is whole: no table cut).
constexpr double kDimensionTolerance = 0.015;  // relative
constexpr double kAxisToleranceDeg = 1.0;

struct View {
  PointList points;
  Eigen::Vector3d camera;
};

// The camera 3 sizes away from the centre, looking from world direction `direction`.
View view_from(const synth::SolidSpec& spec, const Eigen::Vector3d& direction, std::size_t points,
               double noise, std::uint64_t seed) {
  synth::CloudOptions opts;
  opts.points = points;
  opts.noise_sigma = noise * synth::characteristic_size(spec);
  opts.view = spec.pose.center + 3.0 * synth::characteristic_size(spec) * direction.normalized();
  return {synth::make_synthetic_cloud({spec}, opts, seed).points, *opts.view};
}

Eigen::Vector3d world(const synth::SolidSpec& spec, const Eigen::Vector3d& local) {
  return spec.pose.axes.transpose() * local;
}

// Outward normal of the tetrahedron's face opposite vertex i (centroid at the origin).
Eigen::Vector3d tetrahedron_face_normal(const synth::SolidSpec& spec, int i) {
  return world(spec, -synth::tetrahedron_vertices(1.0)[i].normalized());
}

// Outward normal of the prism side between pentagon vertices k and k+1.
Eigen::Vector3d prism_side_normal(const synth::SolidSpec& spec, int k) {
  const auto v = synth::pentagon_vertices(1.0);
  return world(spec, (v[k] + v[(k + 1) % 5]).normalized());
}


double dimension(const pipeline::ObjectResult& o, const std::string& name) {
  for (const auto& [n, v] : o.dimensions)
    if (n == name) return v;
  ADD_FAILURE() << "no dimension " << name;
  return 0.0;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(std::abs(a.normalized().dot(b.normalized())), 0.0, 1.0)) * 180.0 /
         3.14159265358979323846;
}

struct Case {
  std::uint64_t seed;
  std::size_t points;
  double noise;  // sigma as a share of the solid's size
};

const Case kCases[] = {{1, 5000, 0.0}, {2, 20000, 0.0}, {3, 80000, 0.0}, {4, 20000, 0.002}};

// The one object recognised in a view of `spec`, and where it came from for failure messages.
struct Seen {
  pipeline::ObjectResult object;
  std::string trace;
};

Seen recognise_view(const synth::SolidSpec& spec, const Eigen::Vector3d& direction, const Case& c) {
  const View view = view_from(spec, direction, c.points, c.noise, c.seed);
  const auto r = pipeline::recognize_cloud(view.points, config::PipelineConfig{}, synth::to_string(spec.kind));
  EXPECT_EQ(r.objects.size(), 1u);
  return {r.objects.empty() ? pipeline::ObjectResult{} : r.objects.front(),
          "seed " + std::to_string(c.seed) + ", " + std::to_string(view.points.size()) + " points"};
}

TEST(SingleViewPolyhedra, TetrahedronFromTwoOrThreeFaces) {
  for (const Case& c : kCases) {
    std::mt19937_64 rng(c.seed);
    const double edge = std::uniform_real_distribution<double>(0.5, 40.0)(rng);
    const auto spec = synth::make_solid(ShapeKind::tetrahedron, {edge}, synth::random_pose(rng, 10.0));
    // Between two face normals the camera sees exactly those two faces; opposite a face,
    // the other three.
    const Eigen::Vector3d two = tetrahedron_face_normal(spec, 0) + tetrahedron_face_normal(spec, 1);
    const Eigen::Vector3d three = -tetrahedron_face_normal(spec, 3);
    for (const Eigen::Vector3d& direction : {two, three}) {
      const Seen seen = recognise_view(spec, direction, c);
      const pipeline::ObjectResult& o = seen.object;
      SCOPED_TRACE(seen.trace);
      ASSERT_EQ(o.shape, "tetrahedron") << o.reason;
      EXPECT_TRUE(o.partial);
      EXPECT_NEAR(dimension(o, "edge"), edge, kDimensionTolerance * edge);
      EXPECT_LT((o.center - spec.pose.center).norm(), kDimensionTolerance * edge);
    }
  }
}

TEST(SingleViewPolyhedra, PentagonalPrismFromTwoOrThreeSides) {
  for (const Case& c : kCases) {
    std::mt19937_64 rng(c.seed);
    const double side = std::uniform_real_distribution<double>(0.5, 30.0)(rng);
    const double height = side * std::uniform_real_distribution<double>(0.5, 4.0)(rng);
    const auto spec =
        synth::make_solid(ShapeKind::pentagonal_prism, {side, height}, synth::random_pose(rng, 10.0));
    const Eigen::Vector3d axis = spec.pose.axes.row(0).transpose();
    // Square to two sides: those two alone. Square to a side and up the axis: three sides
    // and a cap.
    const Eigen::Vector3d two = prism_side_normal(spec, 0) + prism_side_normal(spec, 1);
    const Eigen::Vector3d three_and_cap = prism_side_normal(spec, 2) + 0.6 * axis;
    for (const Eigen::Vector3d& direction : {two, three_and_cap}) {
      const Seen seen = recognise_view(spec, direction, c);
      const pipeline::ObjectResult& o = seen.object;
      SCOPED_TRACE(seen.trace);
      ASSERT_EQ(o.shape, "pentagonal_prism") << o.reason;
      EXPECT_TRUE(o.partial);
      EXPECT_NEAR(dimension(o, "side"), side, kDimensionTolerance * side);
      EXPECT_NEAR(dimension(o, "height"), height, kDimensionTolerance * height);
      EXPECT_LT(angle_deg(o.axes.row(0).transpose(), axis), kAxisToleranceDeg);
    }
  }
}

// Boxes show faces at 90 deg, cylinders and cones one cap and a curved side (RANSAC cuts
// it into tangent strips at every angle, a few of them flat enough to pass for faces when
// the cloud is sparse), spheres no face: none may come out as a tetrahedron or a prism.
// Sparse views, half of them square to the axis (where strips are most of what RANSAC
// finds), a third with noise. Without solve.polyhedron_face_share, 3 of these 240 views
// (cylinders 37 and 53, cone 44) came out as prisms.
TEST(SingleViewPolyhedra, OtherSolidsSeenFromOneSideAreNeverTetrahedraOrPrisms) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> extent(0.3, 3.0);
  for (ShapeKind kind : {ShapeKind::cylinder, ShapeKind::cone, ShapeKind::box, ShapeKind::sphere}) {
    for (int i = 0; i < 60; ++i) {
      const std::vector<double> dims = kind == ShapeKind::box      ? std::vector<double>{3.0, extent(rng), extent(rng)}
                                       : kind == ShapeKind::sphere ? std::vector<double>{1.5}
                                                                   : std::vector<double>{1.0, extent(rng)};
      const auto spec = synth::make_solid(kind, dims, synth::random_pose(rng, 5.0));
      Eigen::Vector3d direction(gauss(rng), gauss(rng), gauss(rng));
      if (i % 2) direction = direction.cross(spec.pose.axes.row(0).transpose());
      const std::size_t points = 1500 + static_cast<std::size_t>(i % 5) * 1000;
      const double noise = i % 3 == 2 ? 0.005 : 0.0;
      const View view = view_from(spec, direction, points, noise, 100 + static_cast<std::uint64_t>(i));
      for (const auto& o : pipeline::recognize_cloud(view.points, config::PipelineConfig{}, "other").objects) {
        EXPECT_NE(o.shape, "tetrahedron") << synth::to_string(kind) << " view " << i;
        EXPECT_NE(o.shape, "pentagonal_prism") << synth::to_string(kind) << " view " << i;
      }
    }
  }
}

}  // namespace
}  // namespace cloudshape
