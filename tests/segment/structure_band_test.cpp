// The structure search's node sets, several nodes at a time: the same nodes in the same order as
// the per-node tests (also nodes exactly on the limits); and the largest connected part of a set.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "inlier_reference.hpp"
#include "segment/structure_band.hpp"

namespace cloudshape::segment {
namespace {

using test::eigen_band;

TEST(StructureBand, SameNodesInTheSameOrderAsIsInlier) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double band = 3.0;
  std::size_t total = 0, on_limit = 0;
  for (int trial = 0; trial < 200; ++trial) {
    geometry::Plane p;
    p.normal = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
    p.offset = u(rng);
    NeighbourGraph g;
    const std::size_t size =
        1 + static_cast<std::size_t>(trial) * 7 % 301;  // odd and even counts: the tail too
    for (std::size_t n = 0; n < size; ++n) {
      Point x(u(rng), u(rng), u(rng));
      x -= (p.signed_distance(x) - 0.05 * u(rng)) *
           p.normal;  // near the plane: both sides of the band
      g.nodes.push_back(x);
      g.normals.push_back(
          (p.normal + 0.01 * u(rng) * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)))
              .normalized());
      // Every third node exactly on its distance limit as Eigen computes it: a sum in another
      // order would put some of them outside.
      g.spacing.push_back(n % 3 == 0 ? std::abs(p.signed_distance(x)) / band
                                     : std::abs(0.5 + 0.01 * u(rng)));
    }
    // All nodes, and an ascending subset; the angle limit also exactly at one node's cosine.
    std::vector<std::uint32_t> all, some;
    for (std::uint32_t n = 0; n < size; ++n) {
      all.push_back(n);
      if (u(rng) > -20.0) some.push_back(n);
    }
    const double at_limit = std::abs(g.normals[size / 2].dot(p.normal));
    for (double min_cos : {std::cos(25.0 * 3.14159265358979323846 / 180.0), at_limit}) {
      for (const auto* nodes : {&all, &some}) {
        const std::vector<std::uint32_t> expected = eigen_band(g, *nodes, p, band, min_cos);
        EXPECT_EQ(band_nodes(g, *nodes, p, band, min_cos), expected) << "trial " << trial;
        total += expected.size();
        for (std::uint32_t n : expected) on_limit += n % 3 == 0 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(total, 10000u);    // the band holds nodes
  EXPECT_GT(on_limit, 3000u);  // also on its limit
}

TEST(StructureBand, NonFiniteNodesAreNoInliers) {
  NeighbourGraph g;
  geometry::Plane p;  // z = 0
  for (int n = 0; n < 9; ++n) {
    g.nodes.emplace_back(0.01 * n, 0.0, n == 3 ? NAN : n == 6 ? INFINITY : 0.0);
    g.normals.push_back(Eigen::Vector3d::UnitZ());
    g.spacing.push_back(n == 4 ? NAN : 0.1);
  }
  const std::vector<std::uint32_t> all{0, 1, 2, 3, 4, 5, 6, 7, 8};
  EXPECT_EQ(band_nodes(g, all, p, 3.0, 0.9), (std::vector<std::uint32_t>{0, 1, 2, 5, 7, 8}));
}

TEST(StructureBand, NodesAboveAsTheScalarTestHasThem) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double low = 3.0, high = 3.0 * 2.5;
  std::size_t above_total = 0, near_total = 0, on_bound = 0, lifted = 0;
  for (int trial = 0; trial < 200; ++trial) {
    geometry::Plane p;
    p.normal = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
    p.offset = 10.0 * u(rng);
    NeighbourGraph g;
    std::vector<char> skip;
    const std::size_t size =
        1 + static_cast<std::size_t>(trial) * 13 % 601;  // odd, even, over a block
    for (std::size_t n = 0; n < size; ++n) {
      Point x(10.0 * u(rng), 10.0 * u(rng), 10.0 * u(rng));
      x -= (p.signed_distance(x) - u(rng)) * p.normal;  // both sides, over and beyond the bounds
      const double d = p.signed_distance(x);
      // Heights exactly at 0, low and high as the division computes them; a zero spacing (an
      // infinite height) and a NaN one too.
      const double spacing = n % 7 == 0    ? std::abs(d) / low
                             : n % 7 == 1  ? std::abs(d) / high
                             : n % 11 == 2 ? 0.0
                             : n % 13 == 3 ? NAN
                                           : 0.1 + 0.05 * std::abs(u(rng));
      g.nodes.push_back(n % 17 == 4 ? Point(x - d * p.normal) : x);
      g.normals.push_back(p.normal);
      g.spacing.push_back(spacing);
      skip.push_back(n % 5 == 0 ? 1 : 0);
    }
    std::vector<std::uint32_t> nodes, above, near, expected_above, expected_near;
    for (std::uint32_t n = 0; n < size; ++n) {
      if (n % 9 != 8) nodes.push_back(n);
    }
    // Every other trial lifts the plane by its noise: the nodes up to `lift` above it stand on
    // nothing.
    const double lift = trial % 2 == 0 ? 0.0 : 0.5 + 0.01 * trial;
    for (std::uint32_t n : nodes) {
      const double distance = p.signed_distance(g.nodes[n]);
      const double height = distance / g.spacing[n];
      if (skip[n]) continue;
      if (height > low && height <= high) expected_near.push_back(n);
      on_bound += height == low || height == high ? 1 : 0;
      if (height <= 0.0) continue;
      if (lift > 0.0 && distance <= lift) {
        ++lifted;
        continue;
      }
      expected_above.push_back(n);
    }
    nodes_above(g, nodes, skip, p, low, high, lift, above, near);
    EXPECT_EQ(above, expected_above) << "trial " << trial;
    EXPECT_EQ(near, expected_near) << "trial " << trial;
    above_total += above.size();
    near_total += near.size();
  }
  EXPECT_GT(above_total, 10000u);
  EXPECT_GT(near_total, 1000u);
  EXPECT_GT(on_bound, 1000u);  // heights exactly on the bounds were tested
  EXPECT_GT(lifted, 1000u);    // and nodes within the lift
}

TEST(StructureBand, SplitNodesAsTheFlagsHaveThem) {
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<int> coin(0, 99);
  std::size_t seeds_total = 0;
  for (int trial = 0; trial < 60; ++trial) {
    // Runs of removed and tried nodes as a plane leaves them, and scattered ones; NaN curvatures
    // and ones exactly at the limit; sizes around whole blocks of sixteen and 256.
    const std::size_t size = static_cast<std::size_t>(trial) * 37 % 1100;
    NeighbourGraph g;
    std::vector<char> removed(size), tried(size);
    for (std::size_t n = 0; n < size; ++n) {
      const bool run = (n / 40 + static_cast<std::size_t>(trial)) % 3 == 0;
      removed[n] = static_cast<char>(run ? 1 : coin(rng) < 10 ? 2 : 0);
      tried[n] = static_cast<char>((n / 24) % 4 == 1 || coin(rng) < 5 ? 1 : 0);
      g.curvature.push_back(n % 23 == 0 ? NAN : n % 19 == 0 ? 0.02 : 0.0005 * coin(rng));
      g.nodes.push_back(Point::Zero());
    }
    std::vector<std::uint32_t> active, searched, seeds, expected_active, expected_searched,
        expected_seeds;
    for (std::uint32_t n = 0; n < size; ++n) {
      if (removed[n]) continue;
      expected_active.push_back(n);
      if (tried[n]) continue;
      expected_searched.push_back(n);
      if (g.curvature[n] < 0.02) expected_seeds.push_back(n);
    }
    split_nodes(g, removed, tried, 0.02, active, searched, seeds);
    EXPECT_EQ(active, expected_active) << "trial " << trial;
    EXPECT_EQ(searched, expected_searched) << "trial " << trial;
    EXPECT_EQ(seeds, expected_seeds) << "trial " << trial;
    seeds_total += seeds.size();
  }
  EXPECT_GT(seeds_total, 3000u);
}

// The search as it was written first: a member state per node, a vector per part.
std::vector<std::uint32_t> reference_connected(const NeighbourGraph& g,
                                               const std::vector<std::uint32_t>& members) {
  std::vector<int> state(g.size(), 0);
  for (std::uint32_t n : members) state[n] = 1;
  std::vector<std::uint32_t> best, current, stack;
  for (std::uint32_t seed : members) {
    if (state[seed] != 1) continue;
    current.clear();
    stack.assign(1, seed);
    state[seed] = 2;
    while (!stack.empty()) {
      const std::uint32_t n = stack.back();
      stack.pop_back();
      current.push_back(n);
      g.for_neighbours(n, [&](std::uint32_t m) {
        if (state[m] == 1) {
          state[m] = 2;
          stack.push_back(m);
        }
      });
    }
    if (current.size() > best.size()) best.swap(current);
  }
  return best;
}

TEST(StructureBand, LargestConnectedPartInDepthFirstOrder) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coin(0, 99);
  std::size_t largest = 0;
  for (int trial = 0; trial < 100; ++trial) {
    // A grid of w x h nodes, 8-connected, with some edges missing; members a random subset.
    const std::uint32_t w = 1 + static_cast<std::uint32_t>(trial % 13),
                        h = 1 + static_cast<std::uint32_t>(trial % 7) * 3;
    NeighbourGraph g;
    g.nodes.assign(std::size_t{w} * h, Point::Zero());
    g.adjacency_begin.push_back(0);
    for (std::uint32_t r = 0; r < h; ++r) {
      for (std::uint32_t c = 0; c < w; ++c) {
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const std::int64_t rr = std::int64_t{r} + dr, cc = std::int64_t{c} + dc;
            if ((dr == 0 && dc == 0) || rr < 0 || cc < 0 || rr >= h || cc >= w || coin(rng) < 20)
              continue;
            g.adjacency.push_back(static_cast<std::uint32_t>(rr * w + cc));
          }
        }
        g.adjacency_begin.push_back(static_cast<std::uint32_t>(g.adjacency.size()));
      }
    }
    std::vector<std::uint32_t> members;
    for (std::uint32_t n = 0; n < g.size(); ++n) {
      if (coin(rng) < 60) members.push_back(n);
    }
    if (trial % 2) std::shuffle(members.begin(), members.end(), rng);  // any member order
    const std::vector<std::uint32_t> got = largest_connected(g, members);
    EXPECT_EQ(got, reference_connected(g, members)) << "trial " << trial;
    largest = std::max(largest, got.size());
  }
  EXPECT_GT(largest, 50u);  // parts of many nodes, not only single ones
  EXPECT_TRUE(largest_connected(NeighbourGraph{}, {}).empty());
}

}  // namespace
}  // namespace cloudshape::segment
