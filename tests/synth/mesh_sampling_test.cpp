// Area-weighted mesh sampling on an in-memory unit cube (12 triangles plus a degenerate one).
#include "synth/mesh_sampling.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

struct Mesh {
  PointList vertices;
  std::vector<Triangle> triangles;
};

Mesh unit_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  // Each face as two triangles; vertex index bits are (x, y, z).
  const std::array<std::array<std::uint32_t, 4>, 6> quads{
      {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  m.triangles.push_back({0, 0, 1});  // degenerate: must never be sampled
  return m;
}

TEST(MeshSampling, PointsLieOnTheCubeAndFacesShareEvenly) {
  std::mt19937_64 rng(41);
  const Mesh cube = unit_cube();
  const std::size_t n = 120000;
  const PointList points = sample_mesh_surface(cube.vertices, cube.triangles, n, rng);
  ASSERT_EQ(points.size(), n);
  std::array<std::size_t, 6> per_face{};
  for (const auto& p : points) {
    const Eigen::Vector3d q = p - Eigen::Vector3d::Constant(0.5);
    EXPECT_NEAR(q.cwiseAbs().maxCoeff(), 0.5, 1e-12);
    EXPECT_LE(q.cwiseAbs().maxCoeff(), 0.5 + 1e-12);
    int axis;
    q.cwiseAbs().maxCoeff(&axis);
    ++per_face[2 * axis + (q[axis] > 0 ? 1 : 0)];
  }
  const double sigma = std::sqrt((1.0 / 6) * (5.0 / 6) / n);
  for (std::size_t count : per_face) EXPECT_NEAR(count / double(n), 1.0 / 6, 3 * sigma);
  EXPECT_NEAR(mesh_area(cube.vertices, cube.triangles), 6.0, 1e-12);
}

TEST(MeshSampling, TriangleInteriorIsUniform) {
  std::mt19937_64 rng(42);
  const PointList v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::size_t n = 100000;
  const PointList points = sample_mesh_surface(v, {{0, 1, 2}}, n, rng);
  // The corner triangle x + y < 1/2 holds a quarter of the area.
  std::size_t corner = 0;
  for (const auto& p : points) corner += (p.x() + p.y() < 0.5) ? 1 : 0;
  EXPECT_NEAR(corner / double(n), 0.25, 3 * std::sqrt(0.25 * 0.75 / n));
}

TEST(MeshSampling, RejectsBadIndicesAndZeroArea) {
  std::mt19937_64 rng(43);
  const PointList v{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_THROW(sample_mesh_surface(v, {{0, 1, 3}}, 10, rng), std::invalid_argument);
  EXPECT_THROW(sample_mesh_surface(v, {{0, 1, 2}}, 10, rng), std::invalid_argument);
  EXPECT_THROW(sample_mesh_surface(v, {}, 10, rng), std::invalid_argument);
}

}  // namespace
}  // namespace cloudshape::synth
