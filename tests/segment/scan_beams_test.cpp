// Beams of a lidar frame (scan_beams): each point's beam, and how many beams an object spans; a
// ring arc on the ground lies on one beam, too few for a solid (segment.scan_object_min_beams).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

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
