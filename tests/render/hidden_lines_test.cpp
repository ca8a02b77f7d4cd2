// Which pieces of a wire the drawn points hide.
#include <gtest/gtest.h>

#include <limits>

#include "render/hidden_lines.hpp"

namespace cloudshape::render {
namespace {

// An orthographic view, one pixel per unit, and a depth buffer 100 x 20 pixels whose left half
// holds points at depth 1 (a wall) and whose right half is empty.
struct Scene {
  View view;
  DepthBuffer depth;
  Scene() {
    view.camera = Camera{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), false};
    depth = DepthBuffer{0, 0, 100, 20, std::vector<float>(100 * 20, std::numeric_limits<float>::infinity()), 1.0, 3.0};
    for (int y = 0; y < 20; ++y)
      for (int x = 0; x < 50; ++x) depth.depth[y * 100 + x] = 1.0f;
  }
};

Wireframe line_at_depth(double z, bool outline) {
  Wireframe w;
  w.lines.push_back({{Eigen::Vector3d(5.0, 10.0, z), Eigen::Vector3d(95.0, 10.0, z)}, false, outline});
  return w;
}

TEST(HiddenLines, AWireBehindThePointsIsHiddenWhereTheyAreAndShownBeyond) {
  const Scene s;
  const std::vector<WirePiece> pieces = wire_pieces(s.view, line_at_depth(10.0, false), s.depth);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_TRUE(pieces[0].hidden);
  EXPECT_FALSE(pieces[1].hidden);
  EXPECT_NEAR(pieces[0].from.x(), 5.0, 1e-9);
  EXPECT_NEAR(pieces[1].to.x(), 95.0, 1e-9);
  // The verdict changes within a piece (3 pixels) plus the two pixels looked around, of the wall's edge.
  EXPECT_NEAR(pieces[0].to.x(), 50.0, 5.5);
  EXPECT_DOUBLE_EQ(pieces[0].to.x(), pieces[1].from.x());
}

TEST(HiddenLines, AWireOnOrInFrontOfThePointsAndAnOutlineAreNeverHidden) {
  const Scene s;
  // Behind the wall by less than the tolerance (5% of the wire's length 90), and in front of it.
  for (double z : {5.0, 0.5}) {
    const std::vector<WirePiece> pieces = wire_pieces(s.view, line_at_depth(z, false), s.depth);
    ASSERT_EQ(pieces.size(), 1u) << z;
    EXPECT_FALSE(pieces[0].hidden) << z;
  }
  const std::vector<WirePiece> outline = wire_pieces(s.view, line_at_depth(10.0, true), s.depth);
  ASSERT_EQ(outline.size(), 1u);
  EXPECT_FALSE(outline[0].hidden);
}

}  // namespace
}  // namespace cloudshape::render
