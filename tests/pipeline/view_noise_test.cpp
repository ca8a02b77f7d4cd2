// A view's noise off its surface, read with neighbours chosen by their rays from the sensor.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/kdtree.hpp"
#include "noisy_view.hpp"
#include "pipeline/surface_noise.hpp"
#include "pipeline/view_noise.hpp"

namespace cloudshape {
namespace {

using testing::noisy_view;

// Face on, 6 mm of noise along the rays (a Kinect's at 1.8 m), nearly twice the pixels' spacing:
// the rays read it within 10%, the nearest points in space less than half of it.
TEST(ViewNoise, ADepthCamerasNoiseIsReadAlongItsRays) {
  const double noise = 0.006;
  const PointList points = noisy_view(noise, 0.0, 3);
  const double read = pipeline::noise_along_view(points, Point::Zero(), 16);
  EXPECT_NEAR(read, noise, 0.1 * noise);
  const geometry::KdTree tree(points);
  EXPECT_LT(pipeline::surface_noise(points, tree, 16), 0.5 * noise);
}

// Turned 45 degrees away, the noise along the rays lies off the surface by its cosine.
TEST(ViewNoise, ATurnedFaceReadsItsNoiseOffTheSurface) {
  const double noise = 0.006;
  const double tilt = 0.25 * 3.14159265358979323846;
  const PointList points = noisy_view(noise, tilt, 4);
  EXPECT_NEAR(pipeline::noise_along_view(points, Point::Zero(), 16), noise * std::cos(tilt),
              0.1 * noise);
}

// A noise-free face reads none; fewer points than a neighbourhood read nothing.
TEST(ViewNoise, NoneWithoutNoiseOrPoints) {
  EXPECT_LT(pipeline::noise_along_view(noisy_view(0.0, 0.3, 5), Point::Zero(), 16), 1e-9);
  const PointList few{Point(0, 0, 1), Point(0.01, 0, 1), Point(0, 0.01, 1)};
  EXPECT_EQ(pipeline::noise_along_view(few, Point::Zero(), 16), 0.0);
}

}  // namespace
}  // namespace cloudshape
