// Concave creases in an organized cloud: a fold between two flat faces (one box on another turned
// a little, a can against a box) is a crease, a ridge and the evenly turning inside of a bowl are
// not.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "captured_scene.hpp"
#include "config/pipeline_config.hpp"
#include "segment/neighbour_graph.hpp"
#include "segment/segment_scene.hpp"

namespace cloudshape::segment {
namespace {

constexpr std::size_t kWidth = 120, kHeight = 60;
constexpr double kFocal = 100.0;
constexpr double kPi = 3.14159265358979323846;

// A pinhole camera at the origin looking along +z at a surface z = depth(x), the same in every
// row: each pixel's ray meets it where z = depth(x) and x = z (c - kWidth / 2) / kFocal.
struct Frame {
  PointList points;
  GridLayout grid;
};

Frame frame(const std::function<double(double)>& depth) {
  Frame f;
  f.grid.width = kWidth;
  f.grid.height = kHeight;
  for (std::size_t r = 0; r < kHeight; ++r) {
    for (std::size_t c = 0; c < kWidth; ++c) {
      const double ray_x = (static_cast<double>(c) - kWidth / 2.0 + 0.5) / kFocal;
      double z = 1.0;
      for (int it = 0; it < 60; ++it)
        z = depth(ray_x * z);  // a fixed point: the slopes are under 1
      const double ray_y = (static_cast<double>(r) - kHeight / 2.0 + 0.5) / kFocal;
      f.points.emplace_back(ray_x * z, ray_y * z, z);
      f.grid.pixel.push_back(static_cast<std::uint32_t>(r * kWidth + c));
    }
  }
  return f;
}

config::SegmentConfig one_node_per_pixel() {
  config::SegmentConfig cfg = config::PipelineConfig{}.segment;
  cfg.target_nodes = static_cast<std::int64_t>(kWidth * kHeight);
  return cfg;
}

// Creases per image column (a node per pixel, so node n is pixel n).
std::vector<std::size_t> creases_per_column(const NeighbourGraph& g) {
  std::vector<std::size_t> per_column(kWidth, 0);
  if (g.crease.empty()) return per_column;
  for (std::uint32_t n = 0; n < g.size(); ++n) per_column[n % kWidth] += g.crease[n] ? 1 : 0;
  return per_column;
}

// Two flat faces meeting down the middle column, each turned `half_degrees` towards the sensor.
double fold(double x, double half_degrees) {
  return 1.5 - std::tan(half_degrees * kPi / 180.0) * std::abs(x);
}

TEST(ConcaveCrease, AFoldBetweenTwoFlatFacesIsACrease) {
  // Faces 30 degrees apart: their normals turn 15 degrees each side of the fold, under
  // smooth_degrees (10) per node and too gently for a curvature edge.
  const Frame f = frame([](double x) { return fold(x, 15.0); });
  const NeighbourGraph g = build_organized_graph(f.points, f.grid, one_node_per_pixel());
  ASSERT_EQ(g.size(), f.points.size());
  const std::vector<std::size_t> per_column = creases_per_column(g);
  // The fold lies between columns 59 and 60; rows within 2 normal windows of the image's top and
  // bottom have no flank to judge by in the vertical and diagonal directions, but the row does.
  EXPECT_EQ(per_column[59], kHeight);
  EXPECT_EQ(per_column[60], kHeight);
  // Flat face beyond the windows that reach the fold: no crease.
  for (std::size_t c = 0; c < kWidth; ++c) {
    if (c + 6 < 59 || c > 60 + 6) {
      EXPECT_EQ(per_column[c], 0u) << "column " << c;
    }
  }
}

TEST(ConcaveCrease, TheFoldCutsTheFacesApart) {
  const Frame f = frame([](double x) { return fold(x, 15.0); });
  config::SegmentConfig cfg = one_node_per_pixel();
  // Two faces this large are walls to the structure test: here only the fold is judged.
  cfg.structure_max_planes = 0;
  const SceneSegmentation s = segment_scene(f.points, f.grid, cfg);
  ASSERT_EQ(s.objects.size(), 2u);
  for (const auto& object : s.objects) {
    bool left = false, right = false;
    for (std::uint32_t i : object) (f.points[i].x() < 0.0 ? left : right) = true;
    EXPECT_NE(left, right) << "a segment spans the fold";
  }
  cfg.crease_degrees = 0.0;
  EXPECT_EQ(segment_scene(f.points, f.grid, cfg).objects.size(), 1u)
      << "without the crease rule the faces are one patch";
}

TEST(ConcaveCrease, ARidgeIsNoCrease) {
  const Frame f = frame([](double x) { return 1.5 + std::tan(15.0 * kPi / 180.0) * std::abs(x); });
  const NeighbourGraph g = build_organized_graph(f.points, f.grid, one_node_per_pixel());
  for (std::size_t c = 0; c < kWidth; ++c)
    EXPECT_EQ(creases_per_column(g)[c], 0u) << "column " << c;
}

TEST(ConcaveCrease, ABowlsEvenlyTurningInsideIsNoCrease) {
  // The inside of a cylinder of radius 1 (axis along the rows, 1.5 away at its deepest), and a
  // crease angle the normals either side of each node turn by more than: only the flanks, which
  // turn half as much again rather than staying flat, tell that this is no fold.
  const Frame f = frame([](double x) { return 0.5 + std::sqrt(std::max(0.0, 1.0 - x * x)); });
  config::SegmentConfig cfg = one_node_per_pixel();
  cfg.normal_radius = 6;
  cfg.crease_degrees = 8.0;
  const NeighbourGraph g = build_organized_graph(f.points, f.grid, cfg);
  const std::size_t mid = 30 * kWidth + 60;
  const double turn = std::acos(g.normals[mid - 6].dot(g.normals[mid + 6])) * 180.0 / kPi;
  ASSERT_GT(turn, cfg.crease_degrees)
      << "the normals either side must turn enough to be a crease by that alone";
  for (std::size_t c = 0; c < kWidth; ++c)
    EXPECT_EQ(creases_per_column(g)[c], 0u) << "column " << c;
}

}  // namespace
}  // namespace cloudshape::segment
