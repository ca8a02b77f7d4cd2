// Stage 2 under a depth camera's noise: a far face whose noise exceeds the fine band is one plane.
#include <gtest/gtest.h>

#include <cmath>

#include "config/stage_configs.hpp"
#include "noisy_view.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/view_noise.hpp"

namespace cloudshape::pipeline {
namespace {

using testing::noisy_view;

constexpr double kPi = 3.14159265358979323846;

// The 12 x 12 cm square 1.8 m off, 6 mm of noise along the rays, its resolution the pixels' 3.4 mm
// spacing: the fine band (0.8 resolutions, 2.7 mm) is narrower than the noise. Without the
// sensor's position the planes took it apart in parallel layers (measured: eight, the largest 34%
// of the points); seen from the sensor the band follows the noise read along the rays (up to the
// coarse band, 1.7 deviations here) and one plane holds 91% of them (the rest outliers of the
// noise, one patch of 31 points). Asserted: at least four layers within 10 degrees of the face,
// none holding 40%; then at most two planes, the first holding 85%, square to the view within 3
// degrees.
TEST(PlanesUnderNoise, AFarNoisyFaceIsOnePlaneNotLayers) {
  const PointList points = noisy_view(0.006, 0.0, 7);
  const double resolution = 1.8 / 525.0;
  const config::PlanesConfig cfg;
  const double n = static_cast<double>(points.size());
  const PlaneSegmentation layered = segment_planes(points, resolution, cfg);
  EXPECT_GE(layered.planes.size(), 4u);
  for (const DetectedPlane& p : layered.planes) {
    EXPECT_GT(std::abs(p.plane.normal.z()), std::cos(10.0 * kPi / 180.0));
    EXPECT_LT(static_cast<double>(p.inliers.size()), 0.4 * n);
  }
  const PlaneSegmentation seen =
      segment_planes(points, resolution, cfg, nullptr, nullptr, Point::Zero());
  ASSERT_GE(seen.planes.size(), 1u);
  EXPECT_LE(seen.planes.size(), 2u);
  EXPECT_GE(static_cast<double>(seen.planes.front().inliers.size()), 0.85 * n);
  EXPECT_GT(std::abs(seen.planes.front().plane.normal.z()), std::cos(3.0 * kPi / 180.0));
  // The noise the band followed travels with the planes for the solver (within 15% of the drawn
  // 6 mm: the face is seen square on); none is read without the sensor's position.
  EXPECT_EQ(seen.view_noise, noise_along_view(points, Point::Zero(), kViewNoiseRays));
  EXPECT_NEAR(seen.view_noise, 0.006, 0.15 * 0.006);
  EXPECT_EQ(layered.view_noise, 0.0);
}

}  // namespace
}  // namespace cloudshape::pipeline
