// Patches of offset flat pieces: faces of two solids touching at a corner come apart, a flat face
// and a curved one stay whole.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "config/pipeline_config.hpp"
#include "segment/planar_pieces.hpp"

namespace cloudshape::segment {
namespace {

struct Sample {
  Point position;
  Eigen::Vector3d normal;
};

// A graph on a cols x rows lattice of unit spacing: a node where `at` gives one, 8-neighbour
// lattice edges between nodes, plus the `extra` edges (lattice cells).
NeighbourGraph lattice_graph(
    int cols, int rows, const std::function<std::optional<Sample>(int, int)>& at,
    const std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>>& extra = {}) {
  NeighbourGraph g;
  std::vector<std::int64_t> index(static_cast<std::size_t>(cols * rows), -1);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::optional<Sample> s = at(c, r);
      if (!s) continue;
      index[static_cast<std::size_t>(r * cols + c)] = static_cast<std::int64_t>(g.nodes.size());
      g.nodes.push_back(s->position);
      g.normals.push_back(s->normal.normalized());
      g.curvature.push_back(0.0);
      g.spacing.push_back(1.0);
    }
  }
  std::vector<std::set<std::uint32_t>> adjacent(g.nodes.size());
  const auto link = [&](int c0, int r0, int c1, int r1) {
    if (c1 < 0 || r1 < 0 || c1 >= cols || r1 >= rows) return;
    const std::int64_t a = index[static_cast<std::size_t>(r0 * cols + c0)];
    const std::int64_t b = index[static_cast<std::size_t>(r1 * cols + c1)];
    if (a < 0 || b < 0) return;
    adjacent[a].insert(static_cast<std::uint32_t>(b));
    adjacent[b].insert(static_cast<std::uint32_t>(a));
  };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          if (dr != 0 || dc != 0) link(c, r, c + dc, r + dr);
    }
  }
  for (const auto& [from, to] : extra) link(from.first, from.second, to.first, to.second);
  g.adjacency_begin.push_back(0);
  for (const auto& row : adjacent) {
    g.adjacency.insert(g.adjacency.end(), row.begin(), row.end());
    g.adjacency_begin.push_back(static_cast<std::uint32_t>(g.adjacency.size()));
  }
  return g;
}

// Every node in patch 0.
std::vector<std::int32_t> one_patch(const NeighbourGraph& g) {
  return std::vector<std::int32_t>(g.size(), 0);
}

// Two faces 30 x 20 nodes, parallel, 6 node spacings apart along their normal, meeting at one
// corner (the lattice joins them there only): as a box turned on another touches its neighbour's
// face.
NeighbourGraph faces_touching_at_a_corner() {
  const Eigen::Vector3d up(0, 0, 1);
  return lattice_graph(60, 40, [&](int c, int r) -> std::optional<Sample> {
    if (c < 30 && r < 20) return Sample{Point(c, r, 0), up};
    if (c >= 30 && r >= 20) return Sample{Point(c, r, 6), up};
    return std::nullopt;
  });
}

// Faces of two solids touching at a corner: two pieces, each face whole in one.
TEST(PlanarPieces, OffsetFacesTouchingAtACornerComeApart) {
  const NeighbourGraph g = faces_touching_at_a_corner();
  std::vector<std::int32_t> patch = one_patch(g);
  std::int32_t patches = 1;
  const config::SegmentConfig cfg = config::PipelineConfig{}.segment;
  ASSERT_TRUE(split_planar_pieces(g, patch, patches, cfg));
  ASSERT_EQ(patches, 2);
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    const bool lower = g.nodes[n].z() < 3.0;
    EXPECT_EQ(patch[n], patch[0] == 0 ? (lower ? 0 : 1) : (lower ? 1 : 0)) << "node " << n;
  }
}

// One flat face with a few node spacings of depth noise on every node (within the band): one
// piece, so not split.
TEST(PlanarPieces, ANoisyFlatFaceStaysWhole) {
  const NeighbourGraph g = lattice_graph(60, 40, [&](int c, int r) -> std::optional<Sample> {
    const double noise = 0.8 * std::sin(1.7 * c + 2.3 * r);
    return Sample{Point(c, r, noise), Eigen::Vector3d(0.02 * std::cos(c), 0.02 * std::sin(r), 1.0)};
  });
  std::vector<std::int32_t> patch = one_patch(g);
  std::int32_t patches = 1;
  EXPECT_FALSE(split_planar_pieces(g, patch, patches, config::PipelineConfig{}.segment));
  EXPECT_EQ(patches, 1);
  EXPECT_EQ(patch, one_patch(g));
}

// A can's side seen over 150 degrees (radius 20 node spacings): every plane through it holds a
// strip of its normals' 10 degrees, so more than three pieces would be needed: not split.
TEST(PlanarPieces, ACurvedSideStaysWhole) {
  const double radius = 20.0;
  const NeighbourGraph g = lattice_graph(53, 40, [&](int c, int r) -> std::optional<Sample> {
    const double angle = (static_cast<double>(c) / radius) - 75.0 * 3.14159265358979323846 / 180.0;
    if (angle > 75.0 * 3.14159265358979323846 / 180.0) return std::nullopt;
    const Eigen::Vector3d normal(std::sin(angle), 0.0, std::cos(angle));
    return Sample{Point(radius * normal.x(), r, radius * normal.z()), normal};
  });
  std::vector<std::int32_t> patch = one_patch(g);
  std::int32_t patches = 1;
  EXPECT_FALSE(split_planar_pieces(g, patch, patches, config::PipelineConfig{}.segment));
  EXPECT_EQ(patches, 1);
}

// Patches under twice min_object_nodes and the switch (piece_max_planes 1) leave every label as it
// was.
TEST(PlanarPieces, SmallPatchesAndTheSwitchLeaveLabels) {
  const NeighbourGraph g = faces_touching_at_a_corner();
  config::SegmentConfig off = config::PipelineConfig{}.segment;
  off.piece_max_planes = 1;
  std::vector<std::int32_t> patch = one_patch(g);
  std::int32_t patches = 1;
  EXPECT_FALSE(split_planar_pieces(g, patch, patches, off));
  config::SegmentConfig large = config::PipelineConfig{}.segment;
  large.min_object_nodes = static_cast<std::int64_t>(g.size());
  EXPECT_FALSE(split_planar_pieces(g, patch, patches, large));
  EXPECT_EQ(patches, 1);
  EXPECT_EQ(patch, one_patch(g));
}

}  // namespace
}  // namespace cloudshape::segment
