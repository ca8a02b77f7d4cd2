// The structure planes' vectorised hypothesis scoring counts exactly the nodes is_inlier's
// Eigen test accepts (also nodes exactly on the limits), and stops only counts that cannot win.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "inlier_reference.hpp"
#include "segment/structure_planes_scoring.hpp"

namespace cloudshape::segment {
namespace {

std::size_t eigen_count(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes, const geometry::Plane& p,
                        double band, double min_cos) {
  return test::eigen_band(g, nodes, p, band, min_cos).size();
}

TEST(StructureScoring, CountsAsIsInlierDoes) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double band = 3.0;
  const double min_cos = std::cos(25.0 * 3.14159265358979323846 / 180.0);
  std::size_t total = 0, boundary_cases = 0, stopped = 0;
  for (int trial = 0; trial < 200; ++trial) {
    geometry::Plane p;
    p.normal = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
    p.offset = u(rng);
    NeighbourGraph g;
    const std::size_t size = 1 + static_cast<std::size_t>(trial) * 7 % 301;  // odd and even counts: the tail too
    std::vector<std::uint32_t> nodes;
    for (std::uint32_t n = 0; n < size; ++n) {
      Point x(u(rng), u(rng), u(rng));
      x -= (p.signed_distance(x) - 0.05 * u(rng)) * p.normal;  // near the plane: both sides of the band
      const Eigen::Vector3d normal = (p.normal + 0.01 * u(rng) * Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng))).normalized();
      double spacing = std::abs(0.5 + 0.01 * u(rng));
      // Every third node exactly on its distance limit as Eigen computes it: a sum in another
      // order would put some of them outside.
      if (n % 3 == 0) {
        spacing = std::abs(p.signed_distance(x)) / band;
        ++boundary_cases;
      }
      g.nodes.push_back(x);
      g.normals.push_back(normal);
      g.spacing.push_back(spacing);
      nodes.push_back(n);
    }
    // The angle limit exactly at one node's cosine.
    const double at_limit = std::abs(g.normals[nodes.size() / 2].dot(p.normal));
    for (double limit : {min_cos, at_limit}) {
      const ScoredNodes scored(g, nodes, band);
      const std::size_t expected = eigen_count(g, nodes, p, band, limit);
      EXPECT_EQ(count_plane_inliers(scored, p, limit), expected) << "trial " << trial;
      // A bound to beat: the exact count above it, else a count no larger than it.
      for (std::size_t beat : {expected / 2, expected, expected + 1, 2 * expected + 10}) {
        const std::size_t got = count_plane_inliers(scored, p, limit, beat);
        if (expected > beat) {
          EXPECT_EQ(got, expected) << "trial " << trial << " beat " << beat;
        } else {
          EXPECT_LE(got, beat) << "trial " << trial << " beat " << beat;
          stopped += got < expected ? 1 : 0;
        }
      }
      total += expected;
    }
  }
  EXPECT_GT(total, 1000u);  // the test holds inliers, not only outliers
  EXPECT_GT(boundary_cases, 1000u);
  EXPECT_GT(stopped, 50u);  // counts that could not win did stop early
}

// Chunks of nearby nodes far from the plane are skipped whole; a chunk lying exactly on its
// limits, or just inside, or just beyond them, is counted as the per-node test counts it.
TEST(StructureScoring, ChunksNearTheirLimitCountAsIsInlierDoes) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double band = 3.0;
  const double min_cos = std::cos(25.0 * 3.14159265358979323846 / 180.0);
  for (int trial = 0; trial < 50; ++trial) {
    geometry::Plane p;
    // Half the planes along an axis: a cluster's box is then as flat as the cluster.
    p.normal = trial % 2 ? Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()
                         : Eigen::Vector3d(Eigen::Vector3d::Unit(trial / 2 % 3)) * (trial % 4 ? 1.0 : -1.0);
    p.offset = 100.0 * u(rng);
    const Eigen::Vector3d a = p.normal.unitOrthogonal(), b = p.normal.cross(a);
    NeighbourGraph g;
    std::vector<std::uint32_t> nodes;
    // Flat clusters parallel to the plane, each at one height: on the limit, a hair inside or
    // beyond it, or far away; spacing 0.1, so the limit is 0.3.
    for (int cluster = 0; cluster < 40; ++cluster) {
      const double height = std::array<double, 5>{0.3, 0.3 * (1 - 1e-15), 0.3 * (1 + 1e-15), 5.0, -40.0}[cluster % 5];
      const Point centre = -p.offset * p.normal + 200.0 * u(rng) * a + 200.0 * u(rng) * b;
      for (int k = 0; k < 64; ++k) {
        Point x = centre + u(rng) * a + u(rng) * b;
        x += (height - p.signed_distance(x)) * p.normal;
        g.nodes.push_back(x);
        g.normals.push_back(p.normal);
        // On the limit as Eigen computes the distance, for the first kind of cluster.
        g.spacing.push_back(cluster % 5 == 0 ? std::abs(p.signed_distance(x)) / band : 0.1);
        nodes.push_back(static_cast<std::uint32_t>(nodes.size()));
      }
    }
    const ScoredNodes scored(g, nodes, band);
    const std::size_t expected = eigen_count(g, nodes, p, band, min_cos);
    EXPECT_EQ(count_plane_inliers(scored, p, min_cos), expected) << "trial " << trial;
    EXPECT_GE(expected, 8u * 64u) << "the clusters on and inside the limit count";
  }
}

}  // namespace
}  // namespace cloudshape::segment
