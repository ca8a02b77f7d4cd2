// The organized grid: pixel i of a camera frame lies on the ray of pixel i (noise and
// quantisation and flying pixels included), a lidar return on its ring's beam; and the labelled PCD
// written from a frame reads back with the same grid, the same points and the same labels.
#include <gtest/gtest.h>

#include <cmath>

#include "io/cloud_writers.hpp"
#include "io/pcd_reader.hpp"
#include "scene_test_support.hpp"

namespace cloudshape::synth {
namespace {

TEST(SceneGrid, EveryPixelLiesOnItsOwnRay) {
  auto options = testing::small_camera();
  options.depth_noise = 0.003;
  options.quantize = true;
  options.flying_pixels = 0.5;
  const SceneCapture c = testing::capture(SceneLayout::stacked, 2, 1.0, options);
  ASSERT_EQ(c.image.width, 160u);
  ASSERT_EQ(c.image.height, 120u);
  ASSERT_EQ(c.image.points.size(), 160u * 120u);
  DepthCamera camera;
  camera.width = 160;
  camera.height = 120;
  std::size_t finite = 0;
  for (std::size_t row = 0; row < 120; ++row) {
    for (std::size_t column = 0; column < 160; ++column) {
      const Eigen::Vector3d& p = c.image.points[row * 160 + column];
      if (!std::isfinite(p.x())) continue;
      ++finite;
      const Eigen::Vector3d ray = camera.pixel_ray(column, row).normalized();
      ASSERT_GT(p.z(), 0.0);
      ASSERT_LT(p.normalized().cross(ray).norm(), 1e-12) << row << "," << column;
    }
  }
  EXPECT_GT(finite, 1000u);
}

TEST(SceneGrid, OrganizedLidarReturnsLieOnTheirBeams) {
  auto options = testing::small_camera();
  options.organized_lidar = true;
  options.rings = 16;
  options.azimuth_step_deg = 1.0;
  SceneRecipe recipe;
  recipe.layout = SceneLayout::lidar;
  recipe.seed = 3;
  const SceneCapture c = capture_scene(recipe, options);
  ASSERT_EQ(c.image.height, 16u);
  ASSERT_EQ(c.image.width, 360u);
  Lidar lidar;
  lidar.rings = 16;
  lidar.azimuth_step_deg = 1.0;
  std::size_t finite = 0;
  for (std::size_t ring = 0; ring < 16; ++ring) {
    for (std::size_t column = 0; column < 360; ++column) {
      const Eigen::Vector3d& p = c.image.points[ring * 360 + column];
      if (!std::isfinite(p.x())) continue;
      ++finite;
      ASSERT_LT(p.normalized().cross(lidar.beam(ring, column)).norm(), 1e-12);
      ASSERT_GT(p.dot(lidar.beam(ring, column)), 0.0);
    }
  }
  // The rings below the horizon reach the floor all round.
  EXPECT_GT(finite, 360u * 8u);
}

TEST(SceneGrid, LabelledPcdReadsBackWithGridAndLabels) {
  const SceneCapture c = testing::capture(SceneLayout::touching, 4);
  for (const auto encoding :
       {io::PcdEncoding::ascii, io::PcdEncoding::binary, io::PcdEncoding::binary_compressed}) {
    const std::string bytes =
        io::encode_labelled_pcd(c.image.points, c.image.labels, 160, 120, encoding);
    const io::CloudFile file = io::read_pcd_buffer(bytes, "scene.pcd");
    ASSERT_EQ(file.grid.width, 160u);
    ASSERT_EQ(file.grid.height, 120u);
    ASSERT_EQ(file.labels.size(), file.points.size());
    ASSERT_EQ(file.grid.pixel.size(), file.points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < c.image.points.size(); ++i) {
      if (c.image.labels[i] == 0) continue;
      ASSERT_LT(k, file.points.size());
      EXPECT_EQ(file.grid.pixel[k], i);
      EXPECT_EQ(file.labels[k], c.image.labels[i]);
      // Written as float: equal to float rounding.
      EXPECT_LT((file.points[k] - c.image.points[i]).norm(), 1e-6 * c.image.points[i].norm());
      ++k;
    }
    EXPECT_EQ(k, file.points.size());
    EXPECT_EQ(file.non_finite_dropped, c.image.points.size() - k);
  }
}

}  // namespace
}  // namespace cloudshape::synth
