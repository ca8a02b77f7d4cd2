// Organized clouds: pixel neighbours are joined only on the same surface (no edge across a depth
// jump), normals face the sensor, every point belongs to a node on its own side of a jump.
#include <gtest/gtest.h>

#include <cmath>

#include "config/pipeline_config.hpp"
#include "segment/neighbour_graph.hpp"
#include "segment/segment_scene.hpp"

namespace cloudshape::segment {
namespace {

constexpr std::size_t kWidth = 80, kHeight = 60;
constexpr double kFocal = 100.0;

// A wall at depth 2 seen by a pinhole camera at the origin, a square board at depth 1.5 in front
// of it (columns 30-49, rows 20-39), and a hole of invalid pixels (rows 5-9, columns 5-14).
struct Frame {
  PointList points;
  GridLayout grid;
  std::vector<char> on_board;
};

Frame frame() {
  Frame f;
  f.grid.width = kWidth;
  f.grid.height = kHeight;
  for (std::size_t r = 0; r < kHeight; ++r) {
    for (std::size_t c = 0; c < kWidth; ++c) {
      if (r >= 5 && r < 10 && c >= 5 && c < 15) continue;
      const bool board = r >= 20 && r < 40 && c >= 30 && c < 50;
      const double z = board ? 1.5 : 2.0;
      f.points.emplace_back((c - kWidth / 2.0) / kFocal * z, (r - kHeight / 2.0) / kFocal * z, z);
      f.grid.pixel.push_back(static_cast<std::uint32_t>(r * kWidth + c));
      f.on_board.push_back(board);
    }
  }
  return f;
}

config::SegmentConfig one_node_per_pixel() {
  config::SegmentConfig cfg = config::PipelineConfig{}.segment;
  cfg.target_nodes = static_cast<std::int64_t>(kWidth * kHeight);
  return cfg;
}

TEST(SegmentOrganized, NoEdgeAcrossADepthJump) {
  const Frame f = frame();
  const NeighbourGraph g = build_organized_graph(f.points, f.grid, one_node_per_pixel());
  ASSERT_EQ(g.size(), f.points.size());
  ASSERT_TRUE(g.viewpoint);
  std::size_t edges = 0;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    g.for_neighbours(n, [&](std::uint32_t m) {
      ++edges;
      EXPECT_NEAR(g.nodes[n].z(), g.nodes[m].z(), 1e-12) << "an edge joins the board and the wall";
    });
  }
  // 8-neighbour grid: most interior pixels have 8 neighbours.
  EXPECT_GT(edges, 6 * g.size());
}

TEST(SegmentOrganized, NormalsFaceTheSensorAndPointsStayOnTheirSide) {
  const Frame f = frame();
  const NeighbourGraph g = build_organized_graph(f.points, f.grid, config::PipelineConfig{}.segment);
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    EXPECT_GT(g.normals[n].dot(-g.nodes[n]), 0.0);
    EXPECT_GT(std::abs(g.normals[n].z()), 0.99) << "both surfaces are fronto-parallel";
  }
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    ASSERT_NE(g.node_of_point[i], kNoNode);
    EXPECT_NEAR(g.nodes[g.node_of_point[i]].z(), f.points[i].z(), 1e-12);
  }
}

TEST(SegmentOrganized, TheBoardAndTheWallAreSeparateObjects) {
  const Frame f = frame();
  const SceneSegmentation s = segment_scene(f.points, f.grid, config::PipelineConfig{}.segment);
  ASSERT_EQ(s.objects.size(), 2u);
  // The wall is larger; the board's object holds exactly the board's points.
  std::size_t board_points = 0;
  for (char b : f.on_board) board_points += b ? 1 : 0;
  ASSERT_EQ(s.objects[1].size(), board_points);
  for (std::uint32_t i : s.objects[1]) EXPECT_TRUE(f.on_board[i]);
}

}  // namespace
}  // namespace cloudshape::segment
