// fit_outline_sides: a face's outline refitted to its border points; the bends a ragged border
// makes are joined or dropped, real corners (convex or not) kept, sides seen along a face fixed.
#include "pipeline/outline_fit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace cloudshape::pipeline::detail {
namespace {

// Border points every `step` along the closed polygon, each pushed off it by Gaussian noise.
std::vector<Eigen::Vector2d> border_of(const std::vector<Eigen::Vector2d>& polygon, double step, double noise,
                                       std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> off(0.0, noise);
  std::vector<Eigen::Vector2d> out;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Eigen::Vector2d a = polygon[k], b = polygon[(k + 1) % polygon.size()];
    const Eigen::Vector2d dir = (b - a).normalized(), normal(dir.y(), -dir.x());
    for (double t = 0.0; t < (b - a).norm(); t += step) out.push_back(a + t * dir + off(rng) * normal);
  }
  return out;
}

// The sides of a counter-clockwise polygon's edges, as the traced outline would give them.
std::vector<OutlineSide> sides_of(const std::vector<Eigen::Vector2d>& polygon) {
  std::vector<OutlineSide> sides;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Eigen::Vector2d a = polygon[k], b = polygon[(k + 1) % polygon.size()];
    const Eigen::Vector2d dir = (b - a).normalized();
    OutlineSide s;
    s.n = Eigen::Vector2d(dir.y(), -dir.x());
    s.d = s.n.dot(a);
    sides.push_back(s);
  }
  return sides;
}

// How far the true edge from a to b is from a side: the larger of its ends' distances from the
// side's line.
double line_error(const OutlineSide& s, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::max(std::abs(a.dot(s.n) - s.d), std::abs(b.dot(s.n) - s.d));
}

OutlineFitParameters params() {
  OutlineFitParameters p;
  p.cell = 1.0;
  return p;
}

const std::vector<Eigen::Vector2d> kSquare = {{0, 0}, {40, 0}, {40, 40}, {0, 40}};

// The traced outline of a square bent twice along its bottom edge by half a cell (a ragged
// border): the bends are joined, four sides left, each within 0.4 cells of the truth (border
// noise 0.3 cells).
TEST(OutlineFit, BendsOfARaggedBorderAreJoined) {
  const auto border = border_of(kSquare, 0.5, 0.3, 1);
  const std::vector<Eigen::Vector2d> traced = {{0, 0}, {13, 0.5}, {27, -0.5}, {40, 0}, {40, 40}, {0, 40}};
  const auto sides = fit_outline_sides(sides_of(traced), border, params());
  ASSERT_EQ(sides.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const Eigen::Vector2d a = kSquare[k], b = kSquare[(k + 1) % 4];
    bool found = false;
    for (const auto& s : sides) found = found || line_error(s, a, b) < 0.4;
    EXPECT_TRUE(found) << "edge " << k;
  }
}

// A corner the grid cut off (a chamfer one cell long): dropped, its neighbours meet within 0.3
// cells of the true corner.
TEST(OutlineFit, ARoundedCornerIsDropped) {
  const auto border = border_of(kSquare, 0.5, 0.1, 2);
  const std::vector<Eigen::Vector2d> traced = {{0, 0}, {39.3, 0}, {40, 0.7}, {40, 40}, {0, 40}};
  const auto sides = fit_outline_sides(sides_of(traced), border, params());
  ASSERT_EQ(sides.size(), 4u);
  double nearest = 1e9;
  for (const auto& s : sides) nearest = std::min(nearest, (s.end - Eigen::Vector2d(40, 0)).norm());
  EXPECT_LT(nearest, 0.3);
}

// An L's six corners, two of them at its inner step, are all real: none joined or dropped, and
// every corner within 0.3 cells of the truth.
TEST(OutlineFit, AnLKeepsItsSixCorners) {
  const std::vector<Eigen::Vector2d> l_shape = {{0, 0}, {40, 0}, {40, 12}, {12, 12}, {12, 40}, {0, 40}};
  const auto border = border_of(l_shape, 0.5, 0.2, 3);
  const auto sides = fit_outline_sides(sides_of(l_shape), border, params());
  ASSERT_EQ(sides.size(), 6u);
  for (const auto& corner : l_shape) {
    double nearest = 1e9;
    for (const auto& s : sides) nearest = std::min(nearest, (s.end - corner).norm());
    EXPECT_LT(nearest, 0.3) << corner.transpose();
  }
}

// A side placed by a face seen along it stays where it was put (a tenth of a cell off the
// border's line) and keeps its label; the bend the trace made next to it joins it.
TEST(OutlineFit, AFixedSideStaysWhereItIs) {
  const auto border = border_of(kSquare, 0.5, 0.2, 4);
  const std::vector<Eigen::Vector2d> traced = {{0, 0}, {20, 0.4}, {40, 0}, {40, 40}, {0, 40}};
  auto sides = sides_of(traced);
  sides[0].n = Eigen::Vector2d(0, -1);
  sides[0].d = 0.1;  // the line y = -0.1
  sides[0].fixed = true;
  sides[0].label = 7;
  const auto fitted = fit_outline_sides(sides, border, params());
  ASSERT_EQ(fitted.size(), 4u);
  int fixed = 0;
  for (const auto& s : fitted) {
    if (!s.fixed) continue;
    ++fixed;
    EXPECT_EQ(s.label, 7);
    EXPECT_DOUBLE_EQ(s.d, 0.1);
    EXPECT_DOUBLE_EQ(s.n.y(), -1.0);
  }
  EXPECT_EQ(fixed, 1);
}

// Each border point ends with the side whose final segment (from the previous side's end to its
// own) is nearest within the band, the later side on a tie, as trying every side for every point
// gives: checked by brute force on a turned L traced as a ragged outline of 48 short sides, with
// outlying points and points far beyond the band.
TEST(OutlineFit, EachBorderPointGoesToTheNearestSideWithinTheBand) {
  const double turn = 0.5;
  const Eigen::Rotation2Dd rot(turn);
  std::vector<Eigen::Vector2d> l_shape = {{0, 0}, {40, 0}, {40, 12}, {12, 12}, {12, 40}, {0, 40}};
  for (auto& p : l_shape) p = rot * p;
  auto border = border_of(l_shape, 0.5, 0.4, 6);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-20.0, 60.0);
  for (int i = 0; i < 200; ++i) border.push_back(rot * Eigen::Vector2d(u(rng), u(rng)));
  std::vector<Eigen::Vector2d> traced;  // each edge cut into 8 pieces, every other corner off by 0.6
  for (std::size_t k = 0; k < l_shape.size(); ++k) {
    const Eigen::Vector2d a = l_shape[k], b = l_shape[(k + 1) % l_shape.size()];
    const Eigen::Vector2d normal = rot * Eigen::Vector2d(0, 1);
    for (int j = 0; j < 8; ++j) traced.push_back(a + (b - a) * (j / 8.0) + (j % 2 ? 0.6 : 0.0) * normal);
  }
  const OutlineFitParameters p = params();
  const auto sides = fit_outline_sides(sides_of(traced), border, p);
  ASSERT_GE(sides.size(), 3u);
  const std::size_t n = sides.size();
  const double band = p.band_cells * p.cell;
  std::size_t assigned = 0;
  for (const auto& q : border) {
    std::size_t best = n;
    double best_d = band;
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d a = sides[(k + n - 1) % n].end, b = sides[k].end;
      const Eigen::Vector2d ab = b - a;
      const double t = ab.squaredNorm() > 0.0 ? std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      const double d = (q - a - t * ab).norm();
      if (d <= best_d) best = k, best_d = d;
    }
    std::size_t holder = n;
    for (std::size_t k = 0; k < n; ++k)
      if (std::find(sides[k].points.begin(), sides[k].points.end(), q) != sides[k].points.end()) holder = k;
    EXPECT_EQ(holder, best) << q.transpose();
    assigned += best < n;
  }
  EXPECT_GT(assigned, border.size() / 2);
  EXPECT_LT(assigned, border.size());
}

// Fewer than three sides, or a border that leaves fewer standing: no outline.
TEST(OutlineFit, FewerThanThreeSidesIsNoOutline) {
  std::vector<OutlineSide> two = sides_of(kSquare);
  two.resize(2);
  EXPECT_TRUE(fit_outline_sides(two, border_of(kSquare, 0.5, 0.1, 5), params()).empty());
}

}  // namespace
}  // namespace cloudshape::pipeline::detail
