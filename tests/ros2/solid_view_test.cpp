// Solids as ROS 2 sees them: each shape's own box from its dimensions, and meshes that are closed,
// turned outwards and of the solid's volume (cone, prisms, tetrahedron).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ros2/detail/solid_meshes.hpp"
#include "ros2/solid_view.hpp"
#include "ros2_test_support.hpp"

namespace cloudshape::ros2 {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-12;

// By the divergence theorem: positive and equal to the volume only for a closed, outward mesh.
double signed_volume(const detail::Triangles& t) {
  double v = 0.0;
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) v += t[i].dot(t[i + 1].cross(t[i + 2])) / 6.0;
  return v;
}

// Closed: every directed edge is matched by the reverse edge of another triangle.
bool closed(const detail::Triangles& t) {
  std::map<std::array<long long, 6>, int> edges;
  const auto key = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    std::array<long long, 6> k;
    for (int i = 0; i < 3; ++i) {
      k[i] = std::llround(a[i] * 1e9);
      k[i + 3] = std::llround(b[i] * 1e9);
    }
    return k;
  };
  for (std::size_t i = 0; i + 2 < t.size(); i += 3) {
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d& a = t[i + e];
      const Eigen::Vector3d& b = t[i + (e + 1) % 3];
      if ((a - b).norm() < 1e-12) continue;  // a degenerate edge (none expected)
      ++edges[key(a, b)];
      --edges[key(b, a)];
    }
  }
  for (const auto& [k, n] : edges) {
    if (n != 0) return false;
  }
  return true;
}

TEST(Ros2SolidMeshes, ConeIsClosedOutwardAndOfItsVolume) {
  const int n = 48;
  const detail::Triangles cone = detail::revolved(3.0, 0.0, 8.0, n);
  EXPECT_TRUE(closed(cone));
  // The mesh is the pyramid over the inscribed n-gon.
  const double polygon_area = 0.5 * n * 9.0 * std::sin(2 * kPi / n);
  EXPECT_NEAR(signed_volume(cone), polygon_area * 8.0 / 3.0, 1e-9);
  for (const Eigen::Vector3d& v : cone) {
    const double radius = std::hypot(v.y(), v.z());
    EXPECT_TRUE(std::abs(radius - 3.0 * (1.0 - v.x() / 8.0)) < 1e-9 || radius < 1e-12) << v.transpose();
  }
}

TEST(Ros2SolidMeshes, FrustumIsClosedOutwardAndOfItsVolume) {
  const int n = 40;
  const detail::Triangles frustum = detail::revolved(3.0, 1.0, 5.0, n);
  EXPECT_TRUE(closed(frustum));
  const double k = 0.5 * n * std::sin(2 * kPi / n);  // n-gon area per squared radius
  EXPECT_NEAR(signed_volume(frustum), 5.0 / 3.0 * k * (9.0 + 3.0 + 1.0), 1e-9);
}

TEST(Ros2SolidMeshes, NonConvexPrismIsClosedOutwardAndOfItsVolume) {
  // An L (area 3) given clockwise: the mesh must turn it round.
  const std::vector<Eigen::Vector2d> l = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  const detail::Triangles prism = detail::prism(l, 4.0);
  EXPECT_TRUE(closed(prism));
  EXPECT_NEAR(signed_volume(prism), 3.0 * 4.0, 1e-12);
  EXPECT_EQ(prism.size(), 3u * (2 * 4 + 2 * 6));  // 4 cap triangles twice, 2 per side
}

TEST(Ros2SolidMeshes, TetrahedronFacesTurnOutwards) {
  const std::array<Eigen::Vector3d, 4> v = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0),
                                            Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)};
  const detail::Triangles t = detail::tetrahedron(v);
  EXPECT_TRUE(closed(t));
  EXPECT_NEAR(signed_volume(t), 1.0 / 6.0, 1e-15);
}

// The view's mesh in the cloud's frame.
detail::Triangles in_cloud_frame(const SolidView& view) {
  detail::Triangles out;
  for (const Eigen::Vector3d& v : view.triangles) {
    out.push_back(view.marker_frame.origin + view.marker_frame.rotation * v);
  }
  return out;
}

void expect_near(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = kTol) {
  EXPECT_LT((a - b).norm(), tol) << a.transpose() << " vs " << b.transpose();
}

TEST(Ros2SolidView, BoxIsItsEdgesAlongItsAxes) {
  const pipeline::ObjectResult o = test::object("box", {{"length", 30}, {"width", 20}, {"height", 10}});
  const auto view = solid_view(o, 32);
  ASSERT_TRUE(view);
  EXPECT_EQ(view->primitive, Primitive::cube);
  expect_near(view->box.frame.origin, o.center);
  EXPECT_LT((view->box.frame.rotation - test::test_rotation()).norm(), kTol);
  expect_near(view->box.size, {30, 20, 10});
  expect_near(view->scale, {30, 20, 10});
}

TEST(Ros2SolidView, CylinderMarkerRunsAlongItsZ) {
  const pipeline::ObjectResult o = test::object("cylinder", {{"radius", 3}, {"height", 8}});
  const auto view = solid_view(o, 32);
  ASSERT_TRUE(view);
  EXPECT_EQ(view->primitive, Primitive::cylinder);
  expect_near(view->scale, {6, 6, 8});
  expect_near(view->marker_frame.rotation.col(2), o.axes.row(0).transpose());
  EXPECT_NEAR(view->marker_frame.rotation.determinant(), 1.0, kTol);
  expect_near(view->box.size, {8, 6, 6});
  expect_near(view->box.frame.origin, o.center);
}

TEST(Ros2SolidView, SphereScaleIsItsDiameter) {
  const auto view = solid_view(test::object("sphere", {{"radius", 2.5}}), 32);
  ASSERT_TRUE(view);
  EXPECT_EQ(view->primitive, Primitive::sphere);
  expect_near(view->scale, {5, 5, 5});
  expect_near(view->box.size, {5, 5, 5});
}

TEST(Ros2SolidView, ConeRisesFromItsBaseAlongAxisZero) {
  const pipeline::ObjectResult o = test::object("cone", {{"radius", 3}, {"height", 8}});
  const auto view = solid_view(o, 32);
  ASSERT_TRUE(view);
  EXPECT_EQ(view->primitive, Primitive::triangles);
  const Eigen::Vector3d axis = o.axes.row(0).transpose();
  expect_near(view->box.frame.origin, o.center + 4.0 * axis);
  expect_near(view->box.size, {8, 6, 6}, 1e-9);
  // The apex is a vertex, 8 along axis 0 from the base centre.
  const detail::Triangles mesh = in_cloud_frame(*view);
  double farthest = 0.0;
  for (const Eigen::Vector3d& v : mesh) farthest = std::max(farthest, (v - o.center).dot(axis));
  EXPECT_NEAR(farthest, 8.0, 1e-9);
}

TEST(Ros2SolidView, PentagonalPrismHasItsSideAndASideFacingAxisOne) {
  const double side = 4.0, height = 7.0;
  const pipeline::ObjectResult o = test::object("pentagonal_prism", {{"side", side}, {"height", height}});
  const auto view = solid_view(o, 32);
  ASSERT_TRUE(view);
  const double apothem = side / (2.0 * std::tan(kPi / 5.0));
  const double circumradius = side / (2.0 * std::sin(kPi / 5.0));
  EXPECT_NEAR(signed_volume(view->triangles), 2.5 * side * apothem * height, 1e-9);
  // Across axis 1: from the vertex opposite the side (-R) to the side itself (+apothem).
  expect_near(view->box.size, {height, apothem + circumradius, 2.0 * circumradius * std::sin(2 * kPi / 5)}, 1e-9);
  const Eigen::Vector3d offset = view->box.frame.origin - o.center;
  EXPECT_NEAR(offset.dot(o.axes.row(1)), 0.5 * (apothem - circumradius), 1e-9);
  // Every vertex is a pentagon corner on one of the two caps.
  for (const Eigen::Vector3d& v : view->triangles) {
    EXPECT_NEAR(std::abs(v.x()), height / 2, 1e-12);
    EXPECT_NEAR(std::hypot(v.y(), v.z()), circumradius, 1e-12);
  }
}

TEST(Ros2SolidView, TetrahedronIsRegularWithVertexZeroOnAxisZero) {
  const double edge = 6.0;
  const pipeline::ObjectResult o = test::object("tetrahedron", {{"edge", edge}});
  const auto view = solid_view(o, 32);
  ASSERT_TRUE(view);
  EXPECT_NEAR(signed_volume(view->triangles), edge * edge * edge / (6.0 * std::sqrt(2.0)), 1e-9);
  for (std::size_t i = 0; i + 2 < view->triangles.size(); i += 3) {
    for (int e = 0; e < 3; ++e) {
      EXPECT_NEAR((view->triangles[i + e] - view->triangles[i + (e + 1) % 3]).norm(), edge, 1e-9);
    }
  }
  const detail::Triangles mesh = in_cloud_frame(*view);
  const Eigen::Vector3d apex = o.center + edge * std::sqrt(6.0) / 4.0 * o.axes.row(0).transpose();
  EXPECT_TRUE(std::any_of(mesh.begin(), mesh.end(), [&](const Eigen::Vector3d& v) { return (v - apex).norm() < 1e-9; }));
}

TEST(Ros2SolidView, FrustumRunsFromItsLargerEndToItsSmaller) {
  const pipeline::ObjectResult o = test::object("frustum", {{"radius", 3}, {"top_radius", 1}, {"height", 5}});
  const auto view = solid_view(o, 40);
  ASSERT_TRUE(view);
  EXPECT_EQ(view->primitive, Primitive::triangles);
  const Eigen::Vector3d axis = o.axes.row(0).transpose();
  expect_near(view->box.frame.origin, o.center + 2.5 * axis, 1e-9);
  expect_near(view->box.size, {5, 6, 6}, 1e-9);
  const double k = 0.5 * 40 * std::sin(2 * kPi / 40);  // 40-gon area per squared radius
  EXPECT_NEAR(signed_volume(view->triangles), 5.0 / 3.0 * k * (9.0 + 3.0 + 1.0), 1e-9);
  for (const Eigen::Vector3d& v : in_cloud_frame(*view)) {
    const double t = (v - o.center).dot(axis);
    const double r = ((v - o.center) - t * axis).norm();
    EXPECT_TRUE(std::abs(t) < 1e-9 || std::abs(t - 5.0) < 1e-9) << v.transpose();
    EXPECT_TRUE(r < 1e-9 || std::abs(r - (t < 2.5 ? 3.0 : 1.0)) < 1e-9) << v.transpose();
  }
}

TEST(Ros2SolidView, PrismIsItsPolygonExtruded) {
  pipeline::ObjectResult o = test::object("prism", {{"height", 4}, {"sides", 6}});
  o.polygon = {{-1, -1}, {1, -1}, {1, 0}, {0, 0}, {0, 1}, {-1, 1}};  // an L of area 3
  const auto view = solid_view(o, 32);
  ASSERT_TRUE(view);
  EXPECT_NEAR(signed_volume(view->triangles), 12.0, 1e-12);
  expect_near(view->box.size, {4, 2, 2});
  expect_near(view->box.frame.origin, o.center);
  o.polygon.resize(2);
  EXPECT_FALSE(solid_view(o, 32));
}

TEST(Ros2SolidView, TetrahedronWithItsOwnVertices) {
  pipeline::ObjectResult o = test::object("tetrahedron", {{"edge", 5}});
  o.vertices = {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(4, 1, 1), Eigen::Vector3d(1, 3, 1), Eigen::Vector3d(1, 1, 7)};
  o.center = Eigen::Vector3d(1.75, 1.5, 2.5);
  const auto view = solid_view(o, 32);
  ASSERT_TRUE(view);
  EXPECT_NEAR(signed_volume(view->triangles), 3.0 * 2.0 * 6.0 / 6.0, 1e-9);
  for (const Eigen::Vector3d& v : in_cloud_frame(*view)) {
    EXPECT_TRUE(std::any_of(o.vertices.begin(), o.vertices.end(),
                            [&](const Eigen::Vector3d& c) { return (c - v).norm() < 1e-9; }))
        << v.transpose();
  }
}

TEST(Ros2SolidView, ExtentIsTheBoxOfAnObjectWithoutASolid) {
  pipeline::ObjectResult o = test::object("unknown", {});
  EXPECT_FALSE(extent_box(o));  // an error result has none
  o.extent.center = Eigen::Vector3d(1, 2, 3);
  o.extent.axes = test::test_rotation().transpose();
  o.extent.size = Eigen::Vector3d(3, 2, 1);
  const auto box = extent_box(o);
  ASSERT_TRUE(box);
  expect_near(box->frame.origin, o.extent.center);
  expect_near(box->size, o.extent.size);
  EXPECT_LT((box->frame.rotation - test::test_rotation()).norm(), kTol);
}

TEST(Ros2SolidView, UnknownMissingOrBadDimensionsHaveNoView) {
  EXPECT_FALSE(solid_view(test::object("unknown", {}), 32));
  EXPECT_FALSE(solid_view(test::object("box", {{"length", 3}, {"width", 2}}), 32));
  EXPECT_FALSE(solid_view(test::object("sphere", {{"radius", 0}}), 32));
  EXPECT_FALSE(solid_view(test::object("cone", {{"radius", std::nan("")}, {"height", 1}}), 32));
  EXPECT_FALSE(solid_view(test::object("a_shape_from_the_future", {{"radius", 1}}), 32));
}

TEST(Ros2SolidView, LeftHandedAxesTurnRightHandedKeepingAxisZero) {
  pipeline::ObjectResult o = test::object("cone", {{"radius", 1}, {"height", 2}});
  o.axes.row(1) = -o.axes.row(1);
  const Eigen::Matrix3d r = object_rotation(o);
  EXPECT_NEAR(r.determinant(), 1.0, kTol);
  expect_near(r.col(0), o.axes.row(0).transpose());
  expect_near(r.col(1), o.axes.row(1).transpose());
  expect_near(r.col(2), -o.axes.row(2).transpose());
}

}  // namespace
}  // namespace cloudshape::ros2
