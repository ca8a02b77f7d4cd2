// A small solid in a large scene (ground and two walls, as a lidar sees a courtyard): the
// experimental structure removal (preprocess.remove_structure) finds it at its own resolution.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape {
namespace {

// Ground 20 x 20 m and two 4 m walls meeting at a corner, every 5 cm with 5 mm noise; a
// sphere of radius 0.3 m at (10, 8, 1.5) with 3 000 points on its whole surface.
PointList courtyard(const Eigen::Vector3d& centre, double radius) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.005);
  PointList points;
  for (double a = 0.0; a <= 20.0; a += 0.05)
    for (double b = 0.0; b <= 20.0; b += 0.05) points.emplace_back(a, b, noise(rng));
  for (double a = 0.0; a <= 20.0; a += 0.05)
    for (double h = 0.05; h <= 4.0; h += 0.05) {
      points.emplace_back(a, 20.0 + noise(rng), h);
      points.emplace_back(20.0 + noise(rng), a, h);
    }
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng)).normalized();
    points.push_back(centre + (radius + noise(rng)) * d);
  }
  return points;
}

TEST(SceneObjects, SmallSphereAmongGroundAndWallsIsFoundWhenStructureRemovalIsOn) {
  const Eigen::Vector3d centre(10.0, 8.0, 1.5);
  const PointList scene = courtyard(centre, 0.3);
  config::PipelineConfig cfg;
  const auto before = pipeline::recognize_cloud(scene, cfg, "courtyard");
  cfg.preprocess.remove_structure = true;
  const auto after = pipeline::recognize_cloud(scene, cfg, "courtyard");
  ASSERT_EQ(after.objects.size(), 1u) << "objects before: " << before.objects.size();
  EXPECT_EQ(after.objects[0].shape, "sphere");
  ASSERT_FALSE(after.objects[0].dimensions.empty());
  EXPECT_NEAR(after.objects[0].dimensions[0].second, 0.3, 0.03 * 0.3);
  EXPECT_LT((after.objects[0].center - centre).norm(), 0.02);
}

}  // namespace
}  // namespace cloudshape
