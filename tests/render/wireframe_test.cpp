// The wireframe of each shape where its pose and dimensions put it (INTERFACE.md conventions).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "render/wireframe.hpp"

namespace cloudshape::render {
namespace {

constexpr double kTol = 1e-9;

Eigen::Matrix3d turned_axes() {
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
       Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return r.transpose();  // rows: axes[0..2]
}

pipeline::ObjectResult object(const std::string& shape,
                              std::vector<std::pair<std::string, double>> dimensions) {
  pipeline::ObjectResult o;
  o.shape = shape;
  o.dimensions = std::move(dimensions);
  o.center = Eigen::Vector3d(0.3, -1.2, 4.0);
  o.axes = turned_axes();
  return o;
}

Eigen::Vector3d axis(const pipeline::ObjectResult& o, int i) { return o.axes.row(i).transpose(); }

std::vector<Eigen::Vector3d> vertices(const Wireframe& w) {
  std::vector<Eigen::Vector3d> out;
  for (const Polyline& l : w.lines)
    for (const Eigen::Vector3d& p : l.points)
      if (std::none_of(out.begin(), out.end(), [&](const Eigen::Vector3d& q) { return (p - q).norm() < 1e-9; }))
        out.push_back(p);
  return out;
}

struct Segment {
  Eigen::Vector3d a, b;
};

std::vector<Segment> segments(const Wireframe& w) {
  std::vector<Segment> out;
  for (const Polyline& l : w.lines) {
    const std::size_t n = l.points.size();
    for (std::size_t k = 0; k + 1 < n + (l.closed ? 1 : 0); ++k) out.push_back({l.points[k], l.points[(k + 1) % n]});
  }
  return out;
}

bool contains(const std::vector<Eigen::Vector3d>& set, const Eigen::Vector3d& p) {
  return std::any_of(set.begin(), set.end(), [&](const Eigen::Vector3d& q) { return (p - q).norm() < 1e-9; });
}

TEST(Wireframe, BoxHasItsEightCornersAndTwelveEdgesAlongTheAxes) {
  const auto o = object("box", {{"length", 3.0}, {"width", 2.0}, {"height", 1.0}});
  const Wireframe w = solid_wireframe(o, Eigen::Vector3d::UnitZ());
  const auto corners = vertices(w);
  ASSERT_EQ(corners.size(), 8u);
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1})
        EXPECT_TRUE(contains(corners, o.center + sx * 1.5 * axis(o, 0) + sy * 1.0 * axis(o, 1) +
                                          sz * 0.5 * axis(o, 2)))
            << sx << sy << sz;
  const auto edges = segments(w);
  ASSERT_EQ(edges.size(), 12u);
  int along[3] = {0, 0, 0};
  const double lengths[3] = {3.0, 2.0, 1.0};
  for (const Segment& e : edges) {
    const Eigen::Vector3d d = e.b - e.a;
    for (int i = 0; i < 3; ++i)
      if (std::abs(std::abs(d.dot(axis(o, i))) - lengths[i]) < kTol && std::abs(d.norm() - lengths[i]) < kTol)
        ++along[i];
  }
  EXPECT_EQ(along[0], 4);
  EXPECT_EQ(along[1], 4);
  EXPECT_EQ(along[2], 4);
}

TEST(Wireframe, CylinderHasRimsAtHalfHeightAndSideLinesFacingTheViewer) {
  const auto o = object("cylinder", {{"radius", 0.5}, {"height", 2.0}});
  const Eigen::Vector3d viewer = (axis(o, 1) + 0.3 * axis(o, 0)).normalized();
  const Wireframe w = solid_wireframe(o, viewer);
  int rim_points = 0, sides = 0;
  for (const Polyline& l : w.lines) {
    if (l.closed) {
      // Every rim point lies at the radius from one of the two end centres, in its plane.
      for (const Eigen::Vector3d& p : l.points) {
        const double t = (p - o.center).dot(axis(o, 0));
        ASSERT_NEAR(std::abs(t), 1.0, kTol);
        const Eigen::Vector3d end = o.center + t * axis(o, 0);
        ASSERT_NEAR((p - end).norm(), 0.5, kTol);
        ++rim_points;
      }
    } else {
      ASSERT_EQ(l.points.size(), 2u);
      const Eigen::Vector3d d = l.points[1] - l.points[0];
      EXPECT_NEAR(std::abs(d.dot(axis(o, 0))), 2.0, kTol);  // parallel to the axis, full height
      EXPECT_NEAR(d.norm(), 2.0, kTol);
      // An outline: its offset from the axis is across the line of sight.
      const Eigen::Vector3d offset = l.points[0] - o.center;
      const Eigen::Vector3d radial = offset - offset.dot(axis(o, 0)) * axis(o, 0);
      EXPECT_NEAR(radial.norm(), 0.5, kTol);
      EXPECT_NEAR(radial.dot(viewer), 0.0, kTol);
      ++sides;
    }
  }
  EXPECT_GE(rim_points, 2 * 32);
  EXPECT_EQ(sides, 2);
}

TEST(Wireframe, ConeHasItsBaseAtTheCentreAndItsApexAlongAxis0) {
  const auto o = object("cone", {{"radius", 1.0}, {"height", 3.0}});
  const Eigen::Vector3d apex = o.center + 3.0 * axis(o, 0);
  const Eigen::Vector3d side_view = axis(o, 2);
  const Wireframe w = solid_wireframe(o, side_view);
  int sides = 0;
  for (const Polyline& l : w.lines) {
    if (l.closed) {
      for (const Eigen::Vector3d& p : l.points) {
        EXPECT_NEAR((p - o.center).dot(axis(o, 0)), 0.0, kTol);
        EXPECT_NEAR((p - o.center).norm(), 1.0, kTol);
      }
      continue;
    }
    ASSERT_EQ(l.points.size(), 2u);
    EXPECT_NEAR((l.points[1] - apex).norm(), 0.0, kTol);
    // Seen square to the axis, the outline starts where the base rim is across the view.
    EXPECT_NEAR((l.points[0] - o.center).dot(side_view), 0.0, kTol);
    ++sides;
  }
  EXPECT_EQ(sides, 2);
  // Seen from above its apex the cone has no outline: four generators show its side.
  const Wireframe from_top = solid_wireframe(o, axis(o, 0));
  EXPECT_EQ(std::count_if(from_top.lines.begin(), from_top.lines.end(), [](const Polyline& l) { return !l.closed; }), 4);
}

TEST(Wireframe, SphereRimIsSquareToTheViewAndEveryCircleOnTheSurface) {
  const auto o = object("sphere", {{"radius", 0.25}});
  const Eigen::Vector3d viewer = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Wireframe w = solid_wireframe(o, viewer);
  ASSERT_FALSE(w.lines.empty());
  for (const Polyline& l : w.lines)
    for (const Eigen::Vector3d& p : l.points) ASSERT_NEAR((p - o.center).norm(), 0.25, kTol);
  for (const Eigen::Vector3d& p : w.lines.front().points) EXPECT_NEAR((p - o.center).dot(viewer), 0.0, kTol);
}

TEST(Wireframe, TetrahedronHasFourCornersOneEdgeApartAroundItsCentre) {
  const auto o = object("tetrahedron", {{"edge", 0.8}});
  const auto corners = vertices(solid_wireframe(o, Eigen::Vector3d::UnitZ()));
  ASSERT_EQ(corners.size(), 4u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < 4; ++a) {
    mean += corners[a] / 4.0;
    for (std::size_t b = a + 1; b < 4; ++b) EXPECT_NEAR((corners[a] - corners[b]).norm(), 0.8, kTol);
  }
  EXPECT_NEAR((mean - o.center).norm(), 0.0, kTol);
  // The solver points axes[0] at a corner.
  EXPECT_TRUE(contains(corners, o.center + 0.8 * std::sqrt(6.0) / 4.0 * axis(o, 0)));
  EXPECT_EQ(segments(solid_wireframe(o, Eigen::Vector3d::UnitZ())).size(), 6u);
}

TEST(Wireframe, PentagonalPrismHasTwoPentagonsOfItsSideWithAFaceAlongAxis1) {
  const auto o = object("pentagonal_prism", {{"side", 0.5}, {"height", 1.5}});
  const Wireframe w = solid_wireframe(o, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(vertices(w).size(), 10u);
  const double apothem = 0.5 / (2.0 * std::tan(M_PI / 5.0));
  bool face_on_axis1 = false;
  int pentagons = 0;
  for (const Polyline& l : w.lines) {
    if (!l.closed) {
      EXPECT_NEAR((l.points[1] - l.points[0]).dot(axis(o, 0)), 1.5, kTol);
      continue;
    }
    ASSERT_EQ(l.points.size(), 5u);
    ++pentagons;
    for (std::size_t k = 0; k < 5; ++k) {
      const Eigen::Vector3d& a = l.points[k];
      const Eigen::Vector3d& b = l.points[(k + 1) % 5];
      EXPECT_NEAR((a - b).norm(), 0.5, kTol);
      EXPECT_NEAR(std::abs((a - o.center).dot(axis(o, 0))), 0.75, kTol);
      const Eigen::Vector3d mid = 0.5 * (a + b) - o.center;
      const Eigen::Vector3d across = mid - mid.dot(axis(o, 0)) * axis(o, 0);
      if ((across - apothem * axis(o, 1)).norm() < kTol) face_on_axis1 = true;
    }
  }
  EXPECT_EQ(pentagons, 2);
  EXPECT_TRUE(face_on_axis1);
}

TEST(Wireframe, UnknownShapesAndMissingDimensionsDrawNothing) {
  EXPECT_TRUE(solid_wireframe(object("unknown", {}), Eigen::Vector3d::UnitZ()).lines.empty());
  EXPECT_TRUE(solid_wireframe(object("box", {{"length", 1.0}, {"width", 1.0}}), Eigen::Vector3d::UnitZ()).lines.empty());
  EXPECT_TRUE(solid_wireframe(object("sphere", {{"radius", -1.0}}), Eigen::Vector3d::UnitZ()).lines.empty());
  EXPECT_TRUE(solid_wireframe(object("cylinder", {{"radius", NAN}, {"height", 1.0}}), Eigen::Vector3d::UnitZ()).lines.empty());
}

}  // namespace
}  // namespace cloudshape::render
