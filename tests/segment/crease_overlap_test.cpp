// CreaseOverlap: one box's front and top share the edge between them; a box's top and the front
// of a box flush beside it meet that line side by side.
#include <gtest/gtest.h>

#include <cmath>

#include "segment/crease_overlap.hpp"

namespace cloudshape::segment {
namespace {

constexpr double kSpacing = 0.01;
constexpr double kParallelCos = 0.966;  // 15 degrees, the default convex tolerance

// Nodes on a grid of kSpacing over [x0, x1] x [0, depth] (a top, normal +z at height h) or
// [x0, x1] x [0, h] (a front, normal -y at y = 0), given patch `p`.
void add_face(NeighbourGraph& g, std::vector<std::int32_t>& patch, std::int32_t p, bool top, double x0, double x1,
              double h) {
  for (double x = x0; x <= x1 + 1e-9; x += kSpacing) {
    for (double v = 0.0; v <= (top ? 0.2 : h) + 1e-9; v += kSpacing) {
      g.nodes.push_back(top ? Point(x, v, h) : Point(x, 0.0, v));
      g.normals.push_back(top ? Eigen::Vector3d(0, 0, 1) : Eigen::Vector3d(0, -1, 0));
      g.spacing.push_back(kSpacing);
      patch.push_back(p);
    }
  }
}

bool shares(double top_x0, double top_x1, double front_x0, double front_x1) {
  NeighbourGraph g;
  std::vector<std::int32_t> patch;
  add_face(g, patch, 0, true, top_x0, top_x1, 0.3);
  add_face(g, patch, 1, false, front_x0, front_x1, 0.3);
  const std::vector<char> surface(g.size(), 1);
  const CreaseOverlap crease(g, patch, surface, 2, 4.0);
  return crease.shares_crease(0, 1, kParallelCos, 0.5);
}

TEST(SegmentCreaseOverlap, OneBoxsFrontAndTopShareTheirEdge) {
  EXPECT_TRUE(shares(0.0, 0.4, 0.0, 0.4));
  // Part of the top hidden (an occluder, a hole): what is seen still lies along the front's edge.
  EXPECT_TRUE(shares(0.1, 0.4, 0.0, 0.4));
}

TEST(SegmentCreaseOverlap, TwoBoxesSideBySideDoNot) {
  // The top of a box over x in [0, 0.4] and the front of the box beside it, x in [0.4, 0.8].
  EXPECT_FALSE(shares(0.0, 0.4, 0.4, 0.8));
  // Overlapping by a tenth of the shorter span (a step the graph does not resolve) still not.
  EXPECT_FALSE(shares(0.0, 0.4, 0.36, 0.8));
}

TEST(SegmentCreaseOverlap, NotJudgedWithoutACrease) {
  NeighbourGraph g;
  std::vector<std::int32_t> patch;
  add_face(g, patch, 0, true, 0.0, 0.4, 0.3);
  add_face(g, patch, 1, true, 0.5, 0.9, 0.3);  // a parallel patch: no line to judge along
  const std::vector<char> surface(g.size(), 1);
  const CreaseOverlap crease(g, patch, surface, 2, 4.0);
  EXPECT_TRUE(crease.shares_crease(0, 1, kParallelCos, 0.5));
  EXPECT_TRUE(crease.shares_crease(0, 1, kParallelCos, 0.0));
}

}  // namespace
}  // namespace cloudshape::segment
