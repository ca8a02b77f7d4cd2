// Beams of a lidar frame (scan_beams): each point's beam, and how many beams an object spans; a
// ring arc on the ground lies on one beam, too few for a solid (segment.scan_object_min_beams).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "config/pipeline_config.hpp"
#include "segment/scan_beams.hpp"
#include "segment/segment_scene.hpp"
#include "lidar_frames.hpp"
#include "synth/scene_capture.hpp"

namespace cloudshape::segment {
namespace {

const config::SegmentConfig kCfg = config::PipelineConfig{}.segment;

using testing::lidar_frame;

TEST(SegmentScanBeams, AGroundRingArcLiesOnOneBeamTheFrameOnMany) {
  const PointList frame = lidar_frame(1, 16);
  const std::vector<std::int32_t> beam_of = scan_beam_of_points(frame, kCfg);
  std::vector<std::uint32_t> all(frame.size());
  std::iota(all.begin(), all.end(), 0u);
  // The frame's rings that hit something: many beams, never more than the sensor has.
  const std::size_t beams = beams_spanned(beam_of, all);
  EXPECT_GE(beams, 8u);
  EXPECT_LE(beams, 16u);
  // The points of the lowest ring within a 30 degree sector: an arc on the ground, one beam.
  const auto lowest = *std::min_element(beam_of.begin(), beam_of.end(), [](std::int32_t a, std::int32_t b) {
    return (a < 0 ? INT32_MAX : a) < (b < 0 ? INT32_MAX : b);
  });
  std::vector<std::uint32_t> arc;
  for (std::uint32_t i = 0; i < frame.size(); ++i) {
    const double azimuth = std::atan2(frame[i].y(), frame[i].x());
    if (beam_of[i] == lowest && std::abs(azimuth) < 0.26) arc.push_back(i);
  }
  ASSERT_GE(arc.size(), 10u);
  EXPECT_EQ(beams_spanned(beam_of, arc), 1u);
  EXPECT_LT(beams_spanned(beam_of, arc), static_cast<std::size_t>(kCfg.scan_object_min_beams));
}

// A synthetic frame's solid (32 rings, as LidarScene.*) stays; nothing on fewer beams does.
// The tabulated bins are elevation_bin's, for any bin width: on random directions and scales, on
// points exactly on (and a rounding beside) bin edges, near the poles, and on degenerate points.
TEST(SegmentScanBeams, TabulatedBinsAreElevationBins) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), scale_exp(-150.0, 150.0);
  constexpr double kRadians = 3.14159265358979323846 / 180.0;
  std::size_t compared = 0;
  for (double bin : {0.05, 0.07, 0.3, 1.0, 7.0, 45.0, 0.003, 0.002}) {
    const ElevationBins bins(bin);
    EXPECT_EQ(bins.tabulated(), 180.0 / bin <= static_cast<double>(ElevationBins::kMaxTabulated)) << bin;
    std::vector<Point> points;
    for (int i = 0; i < 20000; ++i) {
      points.emplace_back(unit(rng), unit(rng), unit(rng));
      points.back() *= std::pow(10.0, i % 4 == 0 ? scale_exp(rng) : 0.0);
    }
    // On an edge and one rounding either side, at a random azimuth; straight up and down.
    for (int b = -static_cast<int>(90.0 / bin) - 1; b <= static_cast<int>(90.0 / bin) + 1; ++b) {
      const double angle = std::clamp(b * bin, -90.0, 90.0) * kRadians;
      const double azimuth = unit(rng) * 3.14159265358979323846;
      const Point p(std::cos(angle) * std::cos(azimuth), std::cos(angle) * std::sin(azimuth), std::sin(angle));
      points.push_back(p);
      points.emplace_back(p.x(), p.y(), std::nextafter(p.z(), 2.0));
      points.emplace_back(p.x(), p.y(), std::nextafter(p.z(), -2.0));
      points.push_back(p * 3.7);
    }
    for (double z : {1.0, -1.0, 1e-300, 0.0}) {
      points.emplace_back(0.0, 0.0, z);
      points.emplace_back(1e-12, 0.0, z);
    }
    points.emplace_back(1e300, 1e300, 1e300);
    points.emplace_back(std::nan(""), 0.0, 1.0);
    points.emplace_back(0.0, std::numeric_limits<double>::infinity(), 1.0);
    for (const Point& p : points) {
      const std::optional<std::int64_t> expected = elevation_bin(p, bin);
      const std::optional<std::int64_t> got = bins(p);
      ASSERT_EQ(got.has_value(), expected.has_value()) << bin << " " << p.transpose();
      if (!expected) continue;
      ASSERT_EQ(*got, *expected) << bin << " " << p.transpose();
      const std::int64_t e = bins.edge_index(p);
      if (e >= 0) {
        ASSERT_EQ(bins.lowest() + e, *expected) << bin << " " << p.transpose();
      }
      if (bins.tabulated()) {
        EXPECT_GE(*got, bins.lowest());
        EXPECT_LT(*got, bins.lowest() + static_cast<std::int64_t>(bins.span()));
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 160000u);
}

TEST(SegmentScanBeams, NoLidarObjectOnFewerBeamsThanASolidNeeds) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const PointList frame = lidar_frame(seed, 32);
    const SceneSegmentation s = segment_scene(frame, GridLayout{}, kCfg);
    ASSERT_TRUE(s.viewpoint.has_value()) << "seed " << seed;
    ASSERT_FALSE(s.objects.empty()) << "seed " << seed;
    const std::vector<std::int32_t> beam_of = scan_beam_of_points(frame, kCfg);
    for (const auto& o : s.objects) {
      EXPECT_GE(beams_spanned(beam_of, o), static_cast<std::size_t>(kCfg.scan_object_min_beams)) << "seed " << seed;
    }
  }
}

}  // namespace
}  // namespace cloudshape::segment
