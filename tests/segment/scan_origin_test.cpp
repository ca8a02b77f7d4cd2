// A lidar frame in its sensor's frame is told from other clouds by its beams (scan_origin): the
// origin becomes its viewpoint. Synthetic frames (cloudshape-synth scene --layout lidar) with the
// sensor at the origin are; the same frame moved off the origin, and sampled solids, are not.
#include <gtest/gtest.h>

#include "config/pipeline_config.hpp"
#include "segment/scan_origin.hpp"
#include "synth/ground_truth.hpp"
#include "lidar_frames.hpp"
#include "synth/scene_capture.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape::segment {
namespace {

using testing::lidar_frame;

const config::SegmentConfig kCfg = config::PipelineConfig{}.segment;

TEST(SegmentScanOrigin, ALidarFrameSeesFromTheOrigin) {
  for (int rings : {16, 32, 64}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      const PointList frame = lidar_frame(seed, rings);
      ASSERT_GT(frame.size(), 1000u);
      const auto origin = scan_origin(frame, kCfg);
      ASSERT_TRUE(origin.has_value()) << rings << " rings, seed " << seed;
      EXPECT_EQ(origin->norm(), 0.0);
      // Blocks of points binned on a pool: the same beams.
      parallel::ThreadPool pool(3);
      EXPECT_TRUE(scan_origin(frame, kCfg, &pool).has_value()) << rings << " rings, seed " << seed;
    }
  }
}

TEST(SegmentScanOrigin, TheSameFrameOffTheOriginIsNot) {
  PointList frame = lidar_frame(1, 32);
  for (Point& p : frame) p += Point(0.7, -0.4, 1.3);
  EXPECT_FALSE(scan_origin(frame, kCfg).has_value());
  parallel::ThreadPool pool(3);
  EXPECT_FALSE(scan_origin(frame, kCfg, &pool).has_value());
}

TEST(SegmentScanOrigin, SampledSolidsAreNot) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, synth::Pose{}),
      synth::make_solid(synth::ShapeKind::cone, {1.0, 1.0}, synth::Pose{}),
      synth::make_solid(synth::ShapeKind::sphere, {0.5}, synth::Pose{})};
  for (const auto& solid : solids) {
    for (std::uint64_t seed : {1, 2}) {
      synth::CloudOptions opts;
      opts.points = 20000;
      opts.view = Eigen::Vector3d(3, -4, 2);  // seen from one camera, as the accuracy conditions sample
      EXPECT_FALSE(scan_origin(synth::make_synthetic_cloud({solid}, opts, seed).points, kCfg).has_value());
    }
  }
}

}  // namespace
}  // namespace cloudshape::segment
