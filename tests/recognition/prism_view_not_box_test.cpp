// A prism whose visible sides meet at other than a right angle (a hexagon's) or step (an L's
// inner faces) is never a box; a box seen the same ways still is, with its three edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry/polygon.hpp"
#include "new_shapes_support.hpp"
#include "pipeline/recognize.hpp"
#include "synth/pose.hpp"

namespace cloudshape::newshapes {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The camera 3 sizes away, in the cross-section's direction `toward`, raised `elevation` degrees
// towards a cap.
Eigen::Vector3d camera(const synth::SolidMesh& mesh, const synth::Pose& pose, const Eigen::Vector2d& toward,
                       double elevation) {
  const Eigen::Vector3d out =
      (toward.x() * pose.axes.row(1).transpose() + toward.y() * pose.axes.row(2).transpose()).normalized();
  const double e = elevation * kPi / 180.0;
  return mesh.center + 3.0 * mesh.size * (std::cos(e) * out + std::sin(e) * pose.axes.row(0).transpose());
}

struct View {
  pipeline::ObjectResult result;
  synth::SolidMesh mesh;
};

View view_from(const geometry::Polygon2& section, const Eigen::Vector2d& toward, double height, std::uint64_t seed,
               double elevation) {
  std::mt19937_64 rng(seed);
  const synth::Pose pose = synth::random_pose(rng, 100.0);
  const synth::SolidMesh mesh = synth::prism_mesh(section, height, pose);
  const PointList cloud = sample_view(mesh, 8000, 0.005, camera(mesh, pose, toward, elevation), seed + 1);
  return {recognise_one(cloud), mesh};
}

// A squat hexagonal prism (40 high, 100 across its corners) seen across a corner (two sides at
// 120 degrees) or facing a side (three), and its cap; four poses, two elevations. A box's faces
// meet at 90 degrees: a box here is a confident wrong answer (unknown or prism are both honest).
TEST(PrismView, SidesAt120DegreesAreNotABox) {
  const Eigen::Vector2d side_midpoint(std::cos(kPi / 6.0), std::sin(kPi / 6.0));
  for (std::uint64_t seed = 500; seed < 504; ++seed) {
    for (double elevation : {30.0, 50.0}) {
      const Eigen::Vector2d toward = seed % 2 == 0 ? Eigen::Vector2d(1, 0) : side_midpoint;
      const View v = view_from(geometry::regular_polygon(6, 50.0), toward, 40.0, seed, elevation);
      EXPECT_NE(v.result.shape, "box") << "seed " << seed << ", elevation " << elevation;
    }
  }
}

// An L-profile seen into its inner corner: two pairs of parallel faces at different depths (a
// step) and a cap. A box is convex, each of its faces bounds it: never a box.
TEST(PrismView, AnLProfilesStepIsNotABox) {
  const geometry::Polygon2 l_shape = {{-30, -30}, {30, -30}, {30, -10}, {-10, -10}, {-10, 30}, {-30, 30}};
  for (std::uint64_t seed = 700; seed < 704; ++seed) {
    for (double elevation : {20.0, 40.0}) {
      const View v = view_from(l_shape, Eigen::Vector2d(1, 1), 100.0, seed, elevation);
      EXPECT_NE(v.result.shape, "box") << "seed " << seed << ", elevation " << elevation;
    }
  }
}

// A 70 x 50 x 100 box seen the same ways (facing a side, and across a corner): box, each edge
// within 3% of the size (noise 0.5% of it).
TEST(PrismView, ABoxSeenTheSameWayIsStillABox) {
  const geometry::Polygon2 rectangle = {{35, 25}, {-35, 25}, {-35, -25}, {35, -25}};
  for (std::uint64_t seed = 600; seed < 604; ++seed) {
    const Eigen::Vector2d toward = seed % 2 == 0 ? Eigen::Vector2d(1, 0.3) : Eigen::Vector2d(1, 1);
    const View v = view_from(rectangle, toward, 100.0, seed, 30.0);
    ASSERT_EQ(v.result.shape, "box") << "seed " << seed;
    std::vector<double> got = {dimension(v.result, "length"), dimension(v.result, "width"), dimension(v.result, "height")};
    std::sort(got.begin(), got.end());
    const std::vector<double> truth = {50, 70, 100};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], truth[k], 0.03 * v.mesh.size) << "seed " << seed << " edge " << k;
  }
}

// A cap and only two sides seen (a triangle's, a rhombus's, a hexagon's): no three sides give an
// outline, so the cap's traced border must, each hidden side one line, not the ragged border's
// pieces. Three sections, four poses each, camera 45 degrees above the cap, across a corner: a
// prism of the right number of sides in at least 9 of the 12 views (10 today, 5 before the
// outline's sides were refitted to the border and its bends joined), and never a box.
TEST(PrismView, ACapAndTwoSidesGiveTheWholeOutline) {
  const std::vector<geometry::Polygon2> sections = {
      geometry::regular_polygon(3, 50.0),
      {{45, 0}, {0, 28}, {-45, 0}, {0, -28}},
      geometry::regular_polygon(6, 50.0)};
  int right = 0, views = 0;
  for (const geometry::Polygon2& section : sections) {
    for (std::uint64_t seed = 800; seed < 804; ++seed, ++views) {
      const View v = view_from(section, section[0], 80.0, seed, 45.0);
      EXPECT_NE(v.result.shape, "box") << section.size() << " sides, seed " << seed;
      if (v.result.shape != "prism") continue;
      if (static_cast<std::size_t>(std::lround(dimension(v.result, "sides"))) == section.size()) ++right;
    }
  }
  EXPECT_GE(right, 9) << "of " << views;
}

// A rhombus with 72 and 108 degree corners (side 60, prism 80 high), seen across a 108 degree
// corner with its cap: the two sides meet at a regular pentagon's angle, and a pentagonal prism
// fitted to them explains the points as well as the rhombus does. The cap shows four corners:
// never a pentagonal prism, and a prism of 4 sides in most views.
TEST(PrismView, ARhombusAtAPentagonsAngleIsNoPentagonalPrism) {
  const double c = std::cos(72.0 * kPi / 180.0), s = std::sin(72.0 * kPi / 180.0);
  geometry::Polygon2 rhombus = {{0, 0}, {60, 0}, {60 + 60 * c, 60 * s}, {60 * c, 60 * s}};
  const Eigen::Vector2d middle = 0.5 * (rhombus[0] + rhombus[2]);
  for (auto& p : rhombus) p -= middle;
  int four = 0, views = 0;
  for (std::uint64_t seed = 950; seed < 954; ++seed) {
    for (double elevation : {35.0, 55.0}) {
      const View v = view_from(rhombus, rhombus[1], 80.0, seed, elevation);
      ++views;
      EXPECT_NE(v.result.shape, "pentagonal_prism") << "seed " << seed << ", elevation " << elevation;
      if (v.result.shape == "prism" && std::lround(dimension(v.result, "sides")) == 4) ++four;
    }
  }
  EXPECT_GE(2 * four, views) << four << " of " << views;
}

// A squat hexagonal prism (side 50, 39 high) seen with its cap and two or three sides, densely
// (16 000 points): 0.5% noise splits the cap into parallel planes, each a sparse, notched copy of
// it. The cap is placed at its end and its outline traced on all of its pieces: a prism of 6
// sides in at least 15 of 20 views (18 today; 6 when one piece was taken for the cap, the rest
// `unknown`: the smallest piece seemed short of the end, or the outline had notches).
TEST(PrismView, ACapSplitByNoiseIsOneCap) {
  int six = 0, views = 0;
  for (std::uint64_t seed = 1100; seed < 1110; ++seed) {
    for (double elevation : {50.0, 70.0}) {
      std::mt19937_64 rng(seed);
      const synth::Pose pose = synth::random_pose(rng, 100.0);
      const synth::SolidMesh mesh = synth::prism_mesh(geometry::regular_polygon(6, 50.0), 39.0, pose);
      const PointList cloud = sample_view(mesh, 16000, 0.005, camera(mesh, pose, {1, 0.3}, elevation), seed + 1);
      const pipeline::ObjectResult r = recognise_one(cloud);
      ++views;
      EXPECT_NE(r.shape, "box") << "seed " << seed << ", elevation " << elevation;
      if (r.shape == "prism" && std::lround(dimension(r, "sides")) == 6) ++six;
    }
  }
  EXPECT_GE(six, 15) << "of " << views;
}

// A flat triangular prism (100 long, its section 70 across and 22 high) facing the camera with
// its long side, its cap seen 15 or 35 degrees above: the cap holds a few per cent of the points,
// too few to weigh in a scene, where a neighbour may have cut its corner off. Alone in its cloud
// nothing hides part of it: it is a whole triangle, half of the rectangle a box would put there.
// Never a box (12 of the 16 views were before every face of a lone object was judged); a prism of
// three sides in at least 14 of the 16 (16 today).
TEST(PrismView, AGrazingTriangularCapIsNoBoxFace) {
  const geometry::Polygon2 triangle = {{-35, -11}, {35, -11}, {15, 11}};
  int three = 0, views = 0;
  for (std::uint64_t seed = 1000; seed < 1004; ++seed) {
    for (double azimuth : {-110.0, -70.0}) {
      for (double elevation : {15.0, 35.0}) {
        const Eigen::Vector2d toward(std::cos(azimuth * kPi / 180.0),
                                     std::sin(azimuth * kPi / 180.0));
        const View v = view_from(triangle, toward, 100.0, seed, elevation);
        ++views;
        EXPECT_NE(v.result.shape, "box")
            << "seed " << seed << ", azimuth " << azimuth << ", elevation " << elevation;
        if (v.result.shape == "prism" && std::lround(dimension(v.result, "sides")) == 3) ++three;
      }
    }
  }
  EXPECT_GE(three, 14) << "of " << views;
}

// A five-pointed star prism (tips 50 from its axis, inner corners 20, 100 long) seen from 10 or 15
// degrees above its sides, from eight directions around it: two of its sides 108 degrees apart
// meet at a regular tetrahedron's angle as far as their planes go, each a rectangle a fraction of
// the triangle such a tetrahedron would show there. Never a tetrahedron (10 of the 32 views were
// before a regular reading no seen face fills was refused in an object alone in its cloud).
TEST(PrismView, AStarsSidesAreNoTetrahedronsFaces) {
  geometry::Polygon2 star;
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 == 0 ? 50.0 : 20.0, a = k * kPi / 5.0;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  const config::PipelineConfig cfg = shipped_config();
  int views = 0, tetrahedra = 0;
  for (std::uint64_t seed = 1100; seed < 1102; ++seed) {
    std::mt19937_64 rng(seed);
    const synth::Pose pose = synth::random_pose(rng, 100.0);
    const synth::SolidMesh mesh = synth::prism_mesh(star, 100.0, pose);
    for (int direction = 0; direction < 8; ++direction) {
      for (double elevation : {10.0, 15.0}) {
        const double a = (direction * 45.0 + 10.0) * kPi / 180.0;
        const Eigen::Vector3d eye =
            camera(mesh, pose, Eigen::Vector2d(std::cos(a), std::sin(a)), elevation);
        // A view may come apart at a deep notch: every object it gives counts.
        for (const pipeline::ObjectResult& o :
             pipeline::recognize_cloud(sample_view(mesh, 8000, 0.005, eye, seed + 1), cfg, "star")
                 .objects)
          tetrahedra += o.shape == "tetrahedron";
        ++views;
      }
    }
  }
  EXPECT_EQ(tetrahedra, 0) << "of " << views << " views";
}

}  // namespace
}  // namespace cloudshape::newshapes
