// Ring-pattern clouds (a multi-beam lidar over a ground plane): rings lie several times farther
// apart than the points along them, yet every node's normal is the ground's and the rings join.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/stage_configs.hpp"
#include "segment/neighbour_graph.hpp"
#include "synth/range_sensor.hpp"

namespace cloudshape::segment {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct RingScan {
  PointList points;
  Eigen::Vector3d normal;
};

// A 16-beam lidar 0.8-1.6 m over a ground tilted up to 5 degrees: the beams below the horizon
// draw rings from about 3 to 40 m, 0.2 degrees apart along a ring, 1 cm range noise.
RingScan ground_rings(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  synth::Scene scene;
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(5.0 * kPi / 180.0 * u(rng), Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, 0.0).normalized())
          .matrix();
  synth::SceneRectangle ground;
  ground.kind = "plane";
  ground.u = tilt * Eigen::Vector3d::UnitX();
  ground.v = tilt * Eigen::Vector3d::UnitY();
  ground.half_u = ground.half_v = 40.0;
  scene.structure.push_back(ground);
  synth::Lidar lidar;
  lidar.rings = 16;
  lidar.min_elevation_deg = -15.0;
  lidar.max_elevation_deg = -1.0;
  lidar.azimuth_step_deg = 0.2;
  lidar.range_noise = 0.01;
  synth::SensorPose pose;
  pose.position = Eigen::Vector3d(0.0, 0.0, 0.8 + 0.8 * u(rng));
  const synth::RangeImage image = synth::render(scene, lidar, pose, rng);
  RingScan out;
  for (const Point& p : image.points)
    if (p.allFinite()) out.points.push_back(p);
  out.normal = ground.normal();
  return out;
}

std::size_t largest_component(const NeighbourGraph& g) {
  std::vector<char> seen(g.size(), 0);
  std::size_t best = 0;
  std::vector<std::uint32_t> stack;
  for (std::uint32_t s = 0; s < g.size(); ++s) {
    if (seen[s]) continue;
    std::size_t size = 0;
    stack.assign(1, s);
    seen[s] = 1;
    while (!stack.empty()) {
      const std::uint32_t n = stack.back();
      stack.pop_back();
      ++size;
      g.for_neighbours(n, [&](std::uint32_t m) {
        if (!seen[m]) {
          seen[m] = 1;
          stack.push_back(m);
        }
      });
    }
    best = std::max(best, size);
  }
  return best;
}

double share_with_normal(const NeighbourGraph& g, const Eigen::Vector3d& normal, double degrees) {
  std::size_t right = 0;
  for (const Eigen::Vector3d& n : g.normals) right += std::abs(n.dot(normal)) >= std::cos(degrees * kPi / 180.0) ? 1 : 0;
  return static_cast<double>(right) / static_cast<double>(g.size());
}

// Tolerance: 95% of the nodes within 10 degrees of the ground's normal, 95% in one component.
TEST(SegmentRingScan, GroundRingsGiveTheGroundsNormalAndOneSurface) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const RingScan scan = ground_rings(seed);
    ASSERT_GT(scan.points.size(), 10000u);
    const NeighbourGraph g = build_voxel_graph(scan.points, config::SegmentConfig{});
    ASSERT_GT(g.size(), 500u);
    EXPECT_GE(share_with_normal(g, scan.normal, 10.0), 0.95) << "seed " << seed;
    EXPECT_GE(static_cast<double>(largest_component(g)) / static_cast<double>(g.size()), 0.95) << "seed " << seed;
  }
}

// Without the grown neighbourhoods (line_max_neighbours no larger than normal_neighbours) the
// far rings of the same scan stay apart: what the test above holds is not a given.
TEST(SegmentRingScan, WithoutGrownNeighbourhoodsTheRingsStayApart) {
  config::SegmentConfig cfg;
  cfg.line_max_neighbours = cfg.normal_neighbours;
  const RingScan scan = ground_rings(1);
  const NeighbourGraph g = build_voxel_graph(scan.points, cfg);
  EXPECT_LT(static_cast<double>(largest_component(g)) / static_cast<double>(g.size()), 0.95);
}

}  // namespace
}  // namespace cloudshape::segment
