// Simple polygons: an L (non-convex, its centroid outside it) checked against values worked
// out by hand; ear clipping covers the area exactly; a bow-tie is not simple.
#include <gtest/gtest.h>

#include "geometry/polygon.hpp"

namespace cloudshape::geometry {
namespace {

// An L 20 wide and 20 high, arms 6 wide: area 20*6 + 14*6 = 204.
Polygon2 letter_l() { return {{0, 0}, {20, 0}, {20, 6}, {6, 6}, {6, 20}, {0, 20}}; }

TEST(Polygon, AreaPerimeterAndCentroidOfAnL) {
  const Polygon2 l = letter_l();
  EXPECT_NEAR(signed_area(l), 204.0, 1e-12);
  EXPECT_NEAR(perimeter(l), 80.0, 1e-12);
  // Arms [0,6]x[0,20] (120, centroid 3,10) and [6,20]x[0,6] (84, centroid 13,3).
  const Eigen::Vector2d c = area_centroid(l);
  EXPECT_NEAR(c.x(), (120.0 * 3 + 84.0 * 13) / 204.0, 1e-12);
  EXPECT_NEAR(c.y(), (120.0 * 10 + 84.0 * 3) / 204.0, 1e-12);
  EXPECT_GT(signed_distance(l, c), 0.0) << "an L's centroid lies in its notch";
}

TEST(Polygon, SignedDistanceInsideOutsideAndInTheNotch) {
  const Polygon2 l = letter_l();
  EXPECT_NEAR(signed_distance(l, {3, 10}), -3.0, 1e-12);
  EXPECT_NEAR(signed_distance(l, {25, 3}), 5.0, 1e-12);
  EXPECT_NEAR(signed_distance(l, {10, 10}), 4.0, 1e-12);  // nearest: the inner corner's sides
  EXPECT_NEAR(signed_distance(l, {20, 3}), 0.0, 1e-12);
}

TEST(Polygon, EarClippingCoversTheAreaWithNMinusTwoTriangles) {
  const Polygon2 star = {{10, 0}, {3, 3}, {0, 10}, {-3, 3}, {-10, 0}, {-3, -3}, {0, -10}, {3, -3}};
  const auto triangles = triangulate(star);
  ASSERT_EQ(triangles.size(), star.size() - 2);
  double sum = 0.0;
  for (const auto& t : triangles) sum += signed_area({star[t[0]], star[t[1]], star[t[2]]});
  EXPECT_NEAR(sum, signed_area(star), 1e-9);
}

TEST(Polygon, SimplicityTellsABowTie) {
  EXPECT_TRUE(is_simple(letter_l()));
  EXPECT_FALSE(is_simple({{0, 0}, {10, 10}, {10, 0}, {0, 10}}));
}

}  // namespace
}  // namespace cloudshape::geometry
