// An organized cloud's depth noise against its pixel pitch, and the normal window's sample step
// that keeps the noise from tilting a normal beyond a bound.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "segment/detail/depth_noise.hpp"

namespace cloudshape::segment {
namespace {

// A 320 x 240 camera of focal length 2880 pixels (a field narrow enough that every ray meets the
// wall square on) facing a wall 1.2 m off, each pixel's depth with `noise` of independent Gaussian
// noise, or rounded to `step` (a disparity's quantised depth); the wall recedes by `rise` a column.
struct Frame {
  PointList points;
  std::vector<std::int32_t> pixel_point;
  std::vector<double> range;
  static constexpr std::size_t kWidth = 320, kHeight = 240;

  Frame(double noise, double step, std::uint64_t seed, double rise = 0.0)
      : pixel_point(kWidth * kHeight), range(kWidth * kHeight) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    for (std::size_t y = 0; y < kHeight; ++y) {
      for (std::size_t x = 0; x < kWidth; ++x) {
        double z = 1.2 + rise * static_cast<double>(x) + noise * gauss(rng);
        if (step > 0.0) z = step * std::round(z / step);
        const Point ray((static_cast<double>(x) - 160.0) / 2880.0,
                        (static_cast<double>(y) - 120.0) / 2880.0, 1.0);
        const std::size_t i = y * kWidth + x;
        pixel_point[i] = static_cast<std::int32_t>(points.size());
        points.push_back(z * ray);
        range[i] = points.back().norm();
      }
    }
  }
  detail::DepthImage image() const { return {points, pixel_point, range, kWidth, kHeight}; }
};

// The pitch there is 1.2 m / 2880 = 0.42 mm: 0.2 mm and 0.4 mm of noise read as 0.48 and 0.96 of
// it (within 10%, every fourth row read).
TEST(DepthNoise, IndependentNoiseIsReadAgainstThePitch) {
  const double pitch = 1.2 / 2880.0;
  for (double noise : {0.0002, 0.0004}) {
    const Frame frame(noise, 0.0, 7);
    EXPECT_NEAR(detail::depth_noise_ratio(frame.image(), 0.02, 4), noise / pitch,
                0.1 * noise / pitch)
        << noise;
  }
}

// A noise-free wall, and a wall receding 0.03 mm a column whose depth steps by 0.3 mm (a terrace
// every ten pixels, as a Kinect's disparity steps on a table) without independent noise: each
// pixel lies where its neighbours put it, or, but beside a terrace's edge, on their level.
TEST(DepthNoise, SmoothOrSteppedDepthHasNone) {
  EXPECT_LT(detail::depth_noise_ratio(Frame(0.0, 0.0, 1).image(), 0.02, 4), 0.01);
  EXPECT_LT(detail::depth_noise_ratio(Frame(0.0, 0.0003, 1, 0.00003).image(), 0.02, 4), 0.01);
}

// 5 x 5 samples (radius 2): the slope's deviation is the noise over the step over the square root
// of 50 (five rows of offsets -2..2 squared: 10 each). A noise of 1.3 pitches tilts it by 10.4
// degrees at step 1, so a bound of 5 degrees needs step 3 (3.5 degrees; step 2: 5.2); no noise
// keeps the cells' stride; the window stays inside the image.
TEST(DepthNoise, TheWindowSpreadsUntilTheNoiseTiltsLess) {
  EXPECT_EQ(detail::normal_window_step(1.3, 1, 2, 5.0, 640), 3u);
  EXPECT_EQ(detail::normal_window_step(1.3, 4, 2, 5.0, 640), 4u);
  EXPECT_EQ(detail::normal_window_step(0.0, 2, 2, 5.0, 640), 2u);
  EXPECT_EQ(detail::normal_window_step(0.001, 1, 2, 5.0, 640), 1u);
  EXPECT_EQ(detail::normal_window_step(100.0, 1, 2, 5.0, 40), 10u);
}

}  // namespace
}  // namespace cloudshape::segment
