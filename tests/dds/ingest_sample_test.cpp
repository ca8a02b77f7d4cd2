// What ingest does with a received raw cloud (dds::ingest_raw_cloud): bad samples and bad layouts are
// refused with a reason naming the problem, NaN points (and their pixels) are dropped as the file
// readers drop them, and the rest is exactly what recognize_cloud does.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include <fastcdr/exceptions/BadParamException.h>

#include "corrupt_sample.hpp"
#include "dds/checked_type.hpp"
#include "dds/convert.hpp"
#include "dds/ingest_sample.hpp"
#include "dds/topics.hpp"
#include "lidar_frames.hpp"
#include "pipeline/object_clouds.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape::dds {
namespace {
using ::testing::HasSubstr;
using ::testing::Not;
namespace corrupt = cloudshape::testing;
using corrupt::SerializedPayload_t;

PointList box_points(std::size_t n) {
  std::mt19937_64 rng(7);
  return synth::sample_solid_surface(synth::random_solid(synth::ShapeKind::box, rng, 30.0), n, rng);
}

msg::RawCloud raw(std::vector<double> xyz, std::uint32_t object_count = 1) {
  msg::RawCloud m;
  m.header().cloud_id(17);
  m.header().source("scan.pcd");
  m.header().object_count(object_count);
  m.xyz(std::move(xyz));
  return m;
}

// The RawCloudError text for `m`, or "" when it was accepted.
std::string refusal(const msg::RawCloud& m, const config::PipelineConfig& cfg = {}) {
  try {
    ingest_raw_cloud(m, cfg);
  } catch (const RawCloudError& e) {
    return e.what();
  }
  return {};
}

// The same for the sample checks alone (raw_cloud_points), without preprocessing: an accepted
// grid of 2^32 pixels must not reach segmentation in a test.
std::string check_refusal(const msg::RawCloud& m, const config::PipelineConfig& cfg = {}) {
  try {
    raw_cloud_points(m, cfg.input);
  } catch (const RawCloudError& e) {
    return e.what();
  }
  return {};
}

TEST(IngestSample, NonFinitePointsAreDroppedAndTheRestProcessedAsRecognizeDoes) {
  const PointList points = box_points(3000);
  std::vector<double> xyz = to_xyz(points);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  xyz[0] = nan;       // point 0
  xyz[3 * 5 + 1] = inf;  // point 5
  xyz[3 * 9 + 2] = -inf; // point 9
  const auto out = ingest_raw_cloud(raw(xyz), config::PipelineConfig{});

  PointList finite = points;
  for (std::size_t i : {9, 5, 0}) finite.erase(finite.begin() + static_cast<long>(i));
  const RawCloudPoints kept = raw_cloud_points(raw(xyz), config::InputConfig{});
  EXPECT_EQ(kept.non_finite_dropped, 3u);
  EXPECT_EQ(kept.points, finite);

  const config::PipelineConfig cfg;
  const pipeline::ObjectClouds clouds = pipeline::object_clouds(finite, GridLayout{}, cfg.preprocess, cfg.segment);
  const auto& objects = clouds.objects;
  ASSERT_EQ(out.size(), objects.size());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_FALSE(out[0].header().error());
  EXPECT_EQ(out[0].header().object_count(), 1u);
  EXPECT_EQ(out[0].cloud().points_in(), finite.size());
  EXPECT_EQ(from_xyz(out[0].cloud().xyz()), objects[0].points);
  EXPECT_EQ(out[0].cloud().resolution(), objects[0].resolution);
}

// A lidar frame's objects carry the scan lines they lie on, as recognize_cloud's segmentation
// counts them (the solver names only a sphere on two), and the frame's returns about them (the
// solver's free-space test): the same counts and returns, and at least one object on two or more
// lines (the ball).
TEST(IngestSample, ALidarFramesObjectsCarryTheirScanLines) {
  const PointList frame = testing::lidar_frame(1, 32);
  std::vector<double> xyz;
  for (const Point& p : frame) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  const config::PipelineConfig cfg;
  const pipeline::ObjectClouds expected = pipeline::object_clouds(frame, GridLayout{}, cfg.preprocess, cfg.segment);
  const auto out = ingest_raw_cloud(raw(xyz), cfg);
  ASSERT_EQ(out.size(), expected.objects.size());
  std::uint32_t most = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    EXPECT_EQ(out[i].cloud().scan_lines(), expected.objects[i].scan_lines) << i;
    EXPECT_EQ(from_xyz(out[i].cloud().returns_about()), expected.objects[i].returns_about) << i;
    if (out[i].cloud().scan_lines() > 0) {
      EXPECT_FALSE(expected.objects[i].returns_about.empty()) << i;
    }
    most = std::max(most, out[i].cloud().scan_lines());
  }
  EXPECT_GE(most, 2u);
}

TEST(IngestSample, AllNonFiniteIsRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(refusal(raw(std::vector<double>(30, nan))), HasSubstr("all 10 points have NaN or infinite"));
  std::vector<double> mixed(30, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < mixed.size(); i += 3) mixed[i] = 1.0;  // x finite, y and z not
  EXPECT_THAT(refusal(raw(mixed)), HasSubstr("no usable points"));
}

TEST(IngestSample, LengthNotWholeTriplesIsRefused) {
  EXPECT_THAT(refusal(raw({1, 2, 3, 4, 5, 6, 7, 8, 9, 10})), HasSubstr("10 values, not whole x y z triples"));
  EXPECT_THAT(refusal(raw({1, 2})), HasSubstr("not whole x y z triples"));
}

TEST(IngestSample, ZeroPointsIsRefused) { EXPECT_THAT(refusal(raw({})), HasSubstr("no points")); }

TEST(IngestSample, MorePointsThanTheLimitIsRefused) {
  config::PipelineConfig cfg;
  cfg.input.max_points = 999;
  const std::string text = refusal(raw(to_xyz(box_points(1000))), cfg);
  EXPECT_THAT(text, HasSubstr("1000 points, more than input.max_points 999"));
  cfg.input.max_points = 1000;
  EXPECT_EQ(refusal(raw(to_xyz(box_points(1000))), cfg), "");  // the limit itself is allowed
}

TEST(IngestSample, MoreBytesThanTheLimitIsRefused) {
  config::PipelineConfig cfg;
  cfg.input.max_bytes = 24 * 1000 - 1;
  EXPECT_THAT(refusal(raw(to_xyz(box_points(1000))), cfg),
              HasSubstr("24000 bytes of coordinates, more than input.max_bytes 23999"));
}

TEST(IngestSample, ACoordinateBeyondTheLimitIsRefused) {
  // Found by fuzz_ingest: centroids of coordinates near 1e308 overflow to infinity.
  std::vector<double> xyz = to_xyz(box_points(1000));
  xyz[3 * 500 + 1] = -2e30;
  EXPECT_THAT(refusal(raw(xyz)), HasSubstr("beyond input.max_coordinate 1e+30"));
  config::PipelineConfig cfg;
  cfg.input.max_coordinate = 3e30;
  EXPECT_EQ(refusal(raw(xyz), cfg), "");
}

// `n` box points at pixels 0, 3, 6, ... of a 100 x 60 image.
msg::RawCloud organized_raw(std::size_t n) {
  msg::RawCloud m = raw(to_xyz(box_points(n)));
  m.width(100);
  m.height(60);
  for (std::uint32_t i = 0; i < n; ++i) m.pixel().push_back(3 * i);
  return m;
}

TEST(IngestSample, AnOrganizedCloudReachesObjectCloudsWithItsGridAndNaNPixelsDropped) {
  msg::RawCloud m = organized_raw(2000);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.xyz()[3 * 4] = nan;
  m.xyz()[3 * 1999 + 2] = nan;
  const RawCloudPoints kept = raw_cloud_points(m, config::InputConfig{});
  ASSERT_EQ(kept.points.size(), 1998u);
  EXPECT_EQ(kept.grid.width, 100u);
  EXPECT_EQ(kept.grid.height, 60u);
  ASSERT_EQ(kept.grid.pixel.size(), 1998u);
  EXPECT_EQ(kept.grid.pixel[3], 9u);
  EXPECT_EQ(kept.grid.pixel[4], 15u);  // point 4 (pixel 12) was NaN
  EXPECT_EQ(kept.grid.pixel.back(), 3u * 1998);

  const config::PipelineConfig cfg;
  const pipeline::ObjectClouds expected = pipeline::object_clouds(kept.points, kept.grid, cfg.preprocess, cfg.segment);
  const auto out = ingest_raw_cloud(m, cfg);
  ASSERT_EQ(out.size(), expected.objects.size());
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(from_xyz(out[i].cloud().xyz()), expected.objects[i].points);
}

TEST(IngestSample, NoPixelsAndHeightZeroOrOneIsUnorganized) {
  for (std::uint32_t height : {0u, 1u}) {
    msg::RawCloud m = raw(to_xyz(box_points(500)));
    m.width(500);  // a sender may say width = count for a flat cloud, as PCD files do
    m.height(height);
    const RawCloudPoints kept = raw_cloud_points(m, config::InputConfig{});
    EXPECT_FALSE(kept.grid.organized()) << height;
    EXPECT_TRUE(kept.grid.pixel.empty()) << height;
  }
}

TEST(IngestSample, PixelCountOtherThanPointCountIsRefused) {
  msg::RawCloud m = organized_raw(1000);
  m.pixel().pop_back();
  EXPECT_THAT(refusal(m), HasSubstr("pixel holds 999 indices for 1000 points"));  // what the service calls
  m.pixel().clear();  // height 60 promises pixels
  EXPECT_THAT(check_refusal(m), HasSubstr("pixel holds 0 indices for 1000 points"));
}

TEST(IngestSample, PixelsWithoutAnOrganizedHeightAreRefused) {
  msg::RawCloud m = organized_raw(1000);
  m.height(1);
  EXPECT_THAT(check_refusal(m), HasSubstr("pixel holds 1000 indices but height is 1"));
}

TEST(IngestSample, AnOrganizedCloudOfWidthZeroIsRefused) {
  msg::RawCloud m = organized_raw(1000);
  m.width(0);
  EXPECT_THAT(check_refusal(m), HasSubstr("organized cloud of height 60 with width 0"));
}

TEST(IngestSample, APixelOutsideTheGridIsRefused) {
  msg::RawCloud m = organized_raw(1000);
  m.pixel().back() = 6000;  // the first index past 100 x 60
  EXPECT_THAT(check_refusal(m), HasSubstr("pixel[999] = 6000 is outside the 100 x 60 grid"));
  m.pixel().back() = 5999;
  EXPECT_EQ(check_refusal(m), "");
}

TEST(IngestSample, PixelsNotStrictlyIncreasingAreRefused) {
  msg::RawCloud m = organized_raw(1000);
  m.pixel()[7] = m.pixel()[6];
  EXPECT_THAT(check_refusal(m), HasSubstr("pixel[7] = 18 does not follow pixel[6] = 18 (pixels must be strictly increasing)"));
  m.pixel()[7] = 2;
  EXPECT_THAT(check_refusal(m), HasSubstr("pixel[7] = 2 does not follow pixel[6] = 18"));
}

TEST(IngestSample, AGridBeyondThirtyTwoBitPixelsOrTheInputLimitIsRefused) {
  msg::RawCloud m = organized_raw(1000);
  config::PipelineConfig unlimited;
  unlimited.input.max_points = std::numeric_limits<std::int64_t>::max();
  // 32-bit pixel indices cannot address this grid: it is refused before any index is trusted.
  m.width(UINT32_MAX);
  m.height(UINT32_MAX);
  EXPECT_THAT(check_refusal(m, unlimited),
              HasSubstr("grid 4294967295 x 4294967295 = 18446744065119617025 pixels, more than 32-bit pixel indices address"));
  m.width(65536);
  m.height(65537);
  EXPECT_THAT(check_refusal(m, unlimited), HasSubstr("more than 32-bit pixel indices address"));
  m.height(65536);  // exactly 2^32 pixels: addressable
  EXPECT_EQ(check_refusal(m, unlimited), "");
  // An absurd image for the configured input: refused like an absurd point count.
  m.width(3000);
  m.height(2000);
  EXPECT_THAT(check_refusal(m), HasSubstr("grid 3000 x 2000 = 6000000 pixels, more than input.max_points 5000000"));
}

TEST(IngestSample, ARawCloudsOwnObjectCountIsIgnored) {
  // A sensor program that knows nothing of objects leaves object_count at 0.
  const auto out = ingest_raw_cloud(raw(to_xyz(box_points(3000)), 0), config::PipelineConfig{});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].header().object_count(), 1u);
  EXPECT_EQ(out[0].header().source(), "scan.pcd");
  EXPECT_EQ(out[0].header().cloud_id(), 17u);
}

TEST(IngestSample, DegenerateCloudsAreNotRefused) {
  // No solid in them, but readable: they go on and end as "unknown" with a reason downstream.
  for (const std::vector<double>& xyz :
       {std::vector<double>{1, 2, 3}, std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}}) {
    EXPECT_EQ(refusal(raw(xyz)), "");
  }
  std::vector<double> repeated;
  for (int i = 0; i < 500; ++i) repeated.insert(repeated.end(), {4.0, 5.0, 6.0});
  EXPECT_EQ(refusal(raw(repeated)), "");
}

TEST(IngestSample, ARefusedCloudBecomesOneFailedObject) {
  const msg::FilteredCloud f = refused_raw_cloud(raw({1, 2}, 5), "ingest", "xyz holds 2 values");
  EXPECT_TRUE(f.header().error());
  EXPECT_EQ(f.header().error_stage(), "ingest");
  EXPECT_EQ(f.header().error_text(), "xyz holds 2 values");
  EXPECT_EQ(f.header().object_index(), 0u);
  EXPECT_EQ(f.header().object_count(), 1u);  // so the echo does not wait for 5 objects
  EXPECT_EQ(f.header().source(), "scan.pcd");
}

TEST(IngestSample, AnUndecodableSampleBecomesOneFailedObjectOfItsCloudInsteadOfAnException) {
  // Found by fuzz_ingest: a CDR boolean byte that is neither 0 nor 1 makes Fast CDR throw out of
  // the generated type's deserialize, i.e. out of DataReader::take in the service.
  const msg::RawCloud sent = raw({1, 2, 3}, 4);
  const auto payload = corrupt::serialized<msg::RawCloudPubSubType>(sent);
  ASSERT_EQ(payload->data[corrupt::error_flag_byte<msg::RawCloudPubSubType>(sent)], 0);
  corrupt::break_error_flag<msg::RawCloudPubSubType>(sent, *payload);

  msg::RawCloud received;
  msg::RawCloudPubSubType bare;
  EXPECT_THROW(bare.deserialize(payload.get(), &received),
               eprosima::fastcdr::exception::BadParamException);
  CheckedPubSubType<decltype(topics::raw_cloud)> checked;
  received.xyz({9, 9, 9});  // left over from an earlier sample: must not survive
  // Delivered (true), as its cloud's error sample: Fast DDS drops a sample refused with false.
  EXPECT_TRUE(checked.deserialize(payload.get(), &received));
  EXPECT_TRUE(received.header().error());
  EXPECT_EQ(received.header().error_stage(), "receive");
  EXPECT_EQ(received.header().object_count(), 1u);  // one error result completes the cloud
  EXPECT_THAT(received.header().error_text(), HasSubstr("does not deserialize"));
  EXPECT_THAT(received.header().error_text(), Not(HasSubstr("cannot be read")));
  EXPECT_TRUE(received.xyz().empty());
  // The cloud id and source at the start still decode: the error result names the cloud.
  EXPECT_EQ(received.header().cloud_id(), 17u);
  EXPECT_EQ(received.header().source(), "scan.pcd");
}

// Every cloud topic's message starts with its header, so every one keeps its cloud's identity.
template <class Spec>
void expect_undecodable_sample_keeps_its_cloud(const Spec& spec) {
  using Message = typename Spec::Message;
  Message sent;
  sent.header().cloud_id(0xFEEDFACE12ull);
  sent.header().source("cloud of " + std::string(spec.name));
  sent.header().object_index(2);
  sent.header().object_count(3);
  const auto payload = corrupt::serialized<typename Spec::PubSubType>(sent);
  corrupt::break_error_flag<typename Spec::PubSubType>(sent, *payload);
  Message received;
  CheckedPubSubType<Spec> checked;
  EXPECT_TRUE(checked.deserialize(payload.get(), &received)) << spec.name;
  EXPECT_TRUE(received.header().error()) << spec.name;
  EXPECT_EQ(received.header().cloud_id(), 0xFEEDFACE12ull) << spec.name;
  EXPECT_EQ(received.header().source(), sent.header().source()) << spec.name;
  EXPECT_EQ(received.header().object_index(), 0u) << spec.name;
  EXPECT_EQ(received.header().object_count(), 1u) << spec.name;
}

TEST(IngestSample, EveryCloudTopicKeepsTheCloudIdOfAnUndecodableSample) {
  expect_undecodable_sample_keeps_its_cloud(topics::raw_cloud);
  expect_undecodable_sample_keeps_its_cloud(topics::filtered_cloud);
  expect_undecodable_sample_keeps_its_cloud(topics::planes);
  expect_undecodable_sample_keeps_its_cloud(topics::keypoints);
  expect_undecodable_sample_keeps_its_cloud(topics::classified);
  expect_undecodable_sample_keeps_its_cloud(topics::result);
}

TEST(IngestSample, AnUndecodableSampleWhoseCloudIdDoesNotReadSaysSo) {
  const msg::RawCloud sent = raw({1, 2, 3});
  // 4 bytes of encapsulation, then the 8-byte cloud id, then source ("scan.pcd": 4 + 9 bytes).
  const std::vector<std::pair<std::string, std::function<void(SerializedPayload_t&)>>> damages = {
      {"cut in the id", [](SerializedPayload_t& p) { p.length = 4 + 5; }},
      {"cut in the source", [](SerializedPayload_t& p) { p.length = 4 + 8 + 4 + 3; }},
      {"unknown encapsulation", [](SerializedPayload_t& p) { p.data[1] = 0x7F; }},
  };
  for (const auto& [what, damage] : damages) {
    const auto payload = corrupt::serialized<msg::RawCloudPubSubType>(sent);
    damage(*payload);
    msg::RawCloud received;
    received.header().cloud_id(99);  // left over from an earlier sample: must not survive
    received.header().source("earlier.pcd");
    CheckedPubSubType<decltype(topics::raw_cloud)> checked;
    EXPECT_TRUE(checked.deserialize(payload.get(), &received)) << what;
    EXPECT_TRUE(received.header().error()) << what;
    EXPECT_EQ(received.header().cloud_id(), 0u) << what;
    EXPECT_EQ(received.header().source(), "") << what;
    EXPECT_EQ(received.header().object_count(), 1u) << what;
    EXPECT_THAT(received.header().error_text(), HasSubstr("does not deserialize")) << what;
    EXPECT_THAT(received.header().error_text(), HasSubstr("cloud id and source cannot be read"))
        << what;
  }
}

TEST(IngestSample, AnUndecodableStatusSampleIsDropped) {
  msg::ServiceStatus sent;
  sent.service("ingest");
  const auto payload = corrupt::serialized<msg::ServiceStatusPubSubType>(sent);
  payload->length = 4 + 3;  // cut in the service name's length
  msg::ServiceStatus received;
  received.service("planes");  // left over from an earlier sample
  CheckedPubSubType<decltype(topics::status)> checked;
  EXPECT_FALSE(checked.deserialize(payload.get(), &received));
  EXPECT_EQ(received.service(), "");
}

}  // namespace
}  // namespace cloudshape::dds
