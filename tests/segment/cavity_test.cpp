// Open containers kept whole: the concavity measure on exact surfaces, and real Kinect pots whose
// inside, seen over the rim, used to come out as a second object (mosd_learn, SOURCES.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "segment/cavity_join.hpp"
#include "segment/segment_scene.hpp"

namespace cloudshape::segment {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Nodes on the +y half of a unit cylinder (axis z), normals towards the axis (its inside, as a
// sensor on the -y side sees it over the rim) or away from it (its outside).
NeighbourGraph half_cylinder(bool inward_normals) {
  NeighbourGraph g;
  for (int i = 0; i <= 60; ++i) {
    const double a = kPi * i / 60.0;
    for (int k = 0; k < 10; ++k) {
      const Eigen::Vector3d radial(std::cos(a), std::sin(a), 0.0);
      g.nodes.emplace_back(radial + Eigen::Vector3d(0, 0, 0.1 * k));
      g.normals.push_back(inward_normals ? -radial : radial);
    }
  }
  return g;
}

std::vector<std::uint32_t> all_nodes(const NeighbourGraph& g) {
  std::vector<std::uint32_t> n(g.size());
  for (std::uint32_t i = 0; i < g.size(); ++i) n[i] = i;
  return n;
}

TEST(SegmentCavity, InsideOfAHalfCylinderIsConcaveItsOutsideConvexAPlaneNeither) {
  const NeighbourGraph inside = half_cylinder(true);
  const NeighbourGraph outside = half_cylinder(false);
  // Analytic: (1 - 4/pi^2) / sqrt(1 - 4/pi^2 + 0.0825) = 0.72 (0.0825: the spread along z).
  EXPECT_GT(concavity(inside, all_nodes(inside)), 0.5);
  EXPECT_LT(concavity(outside, all_nodes(outside)), -0.5);
  NeighbourGraph plane;
  for (int i = 0; i < 20; ++i) {
    for (int k = 0; k < 20; ++k) {
      plane.nodes.emplace_back(0.1 * i, 0.1 * k, 0.0);
      plane.normals.emplace_back(0.0, 0.0, 1.0);
    }
  }
  EXPECT_NEAR(concavity(plane, all_nodes(plane)), 0.0, 1e-9);
}

const std::filesystem::path kDir = std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real/mosd_learn";

// Share of a labelled object's points (label / 10 == object) that its best-matching segment holds.
double best_segment_share(int frame, std::uint32_t object) {
  const io::CloudFile file = io::read_cloud((kDir / ("learn" + std::to_string(frame) + ".pcd")).string());
  const SceneSegmentation s = segment_scene(file.points, file.grid, config::PipelineConfig{}.segment);
  std::size_t in_object = 0;
  for (std::uint32_t l : file.labels) in_object += l / 10 == object;
  std::size_t best = 0;
  for (const auto& segment : s.objects) {
    std::size_t held = 0;
    for (std::uint32_t i : segment) held += file.labels[i] / 10 == object;
    best = std::max(best, held);
  }
  return in_object > 0 ? static_cast<double>(best) / static_cast<double>(in_object) : 0.0;
}

// The pot of learn36 (object 4) and of learn38 (object 5): its outer front and its inside are cut
// apart by depth jumps at the rim; before the cavity join, neither segment held 45% of it.
TEST(SegmentCavity, AKinectPotsInsideStaysWithItsOutside) {
  if (!std::filesystem::exists(kDir / "learn36.pcd")) {
    const char* ci = std::getenv("CI");
    if (ci && std::string(ci) == "true") ADD_FAILURE() << kDir << " missing on CI";
    GTEST_SKIP() << kDir << " missing";
  }
  EXPECT_GT(best_segment_share(36, 4), 0.85);
  EXPECT_GT(best_segment_share(38, 5), 0.85);
}

}  // namespace
}  // namespace cloudshape::segment
