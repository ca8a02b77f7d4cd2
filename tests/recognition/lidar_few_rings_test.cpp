// Solids off a lidar, on a few scan rings: a ring on a round surface is a curve in a plane, and is
// no flat face of the solid, so a far ball on three rings is a sphere; a box's rings are straight
// runs along its faces, which stay flat faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "config/pipeline_config.hpp"
#include "lidar_frames.hpp"
#include "pipeline/recognize.hpp"
#include "synth/range_sensor.hpp"
#include "synth/scene.hpp"

namespace cloudshape {
namespace {

// A 16-beam lidar's rings, every 2 degrees from -15 to 15, 0.19 degrees of azimuth, 1 cm range
// noise (the SphereCalib sensor's): the returns of `solid` alone, in the lidar's frame at the
// origin, and how many rings hit it. (Alone, the cloud is no lidar frame to the segmentation:
// the object is recognised whole, as its own points.)
PointList scan(const synth::SolidSpec& solid, std::uint64_t seed, std::size_t* rings_hit) {
  synth::Scene scene;
  scene.objects.push_back({solid, 20});
  std::mt19937_64 rng(seed);
  const synth::RangeImage image =
      synth::render(scene, testing::spherecalib_lidar(0.01), synth::SensorPose{}, rng);
  PointList points;
  std::set<std::size_t> rings;
  for (std::size_t i = 0; i < image.points.size(); ++i) {
    if (!image.points[i].allFinite()) continue;
    points.push_back(image.points[i]);
    rings.insert(i / image.width);
  }
  *rings_hit = rings.size();
  return points;
}

const pipeline::ObjectResult& nearest(const std::vector<pipeline::ObjectResult>& objects, const Eigen::Vector3d& c) {
  return *std::min_element(objects.begin(), objects.end(),
                           [&](const auto& a, const auto& b) { return (a.center - c).norm() < (b.center - c).norm(); });
}

synth::SolidSpec at(synth::SolidSpec s, const Eigen::Vector3d& centre) {
  s.pose.center = centre;
  return s;
}

// Balls of radius 0.25-0.35 m, 4.8-5.4 m off, on three rings: a sphere, radius within 5% and
// centre within 5 cm (issue 10's tolerance for the calibration sphere), in every one of 6 draws
// (before, the rings' planes passed for flat faces covering the ball and no solid was named).
TEST(LidarFewRings, ABallOnThreeRingsIsASphere) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  std::mt19937_64 draw(5);
  std::uniform_real_distribution<double> radius_of(0.25, 0.35), range_of(4.8, 5.4), azimuth_of(-3.0, 3.0);
  int tried = 0;
  for (std::uint64_t seed = 1; tried < 6 && seed < 40; ++seed) {
    const double radius = radius_of(draw), range = range_of(draw), azimuth = azimuth_of(draw);
    const Eigen::Vector3d centre(range * std::cos(azimuth), range * std::sin(azimuth), 0.05);
    std::size_t rings = 0;
    const PointList points = scan(at(synth::make_solid(synth::ShapeKind::sphere, {radius}, {}), centre), seed, &rings);
    if (rings != 3) continue;
    ++tried;
    const auto result = pipeline::recognize_cloud(points, cfg, "ball");
    ASSERT_EQ(result.objects.size(), 1u) << "seed " << seed;
    const auto& o = result.objects.front();
    EXPECT_EQ(o.shape, "sphere") << "seed " << seed << ": " << o.reason;
    if (o.shape != "sphere") continue;
    EXPECT_NEAR(o.dimensions.front().second, radius, 0.05 * radius) << "seed " << seed;
    EXPECT_LT((o.center - centre).norm(), 0.05) << "seed " << seed;
  }
  EXPECT_EQ(tried, 6);
}

// Boxes 0.5 x 0.4 x 0.45 m, turned, 2.5-3 m off, on five to seven rings: each ring is a straight
// run along each face it crosses, no arc, so no sphere, cylinder, cone or frustum may be named.
// Measured: all six `unknown`. Seed 6 came out a cone while any solid within inlier_distance of
// the points was taken; that cone leaves them 3.7 times their noise from it
// (solve.scan_noise_ratio). Left: the boxes are not named boxes either. Rings 9 cm apart cover a
// face with lines, and the fill test's cells, twice the spacing along a ring (2 cm), find such a
// face mostly empty, so it does not count as flat; the fill of a face sampled by lines wants the
// cell of the lines' spacing.
TEST(LidarFewRings, ABoxsStraightRingsNameNoRoundSolid) {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  std::mt19937_64 draw(6);
  std::uniform_real_distribution<double> range_of(2.5, 3.0), azimuth_of(-3.0, 3.0), turn_of(0.2, 1.3);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const double range = range_of(draw), azimuth = azimuth_of(draw), turn = turn_of(draw);
    synth::SolidSpec box = synth::make_solid(synth::ShapeKind::box, {0.5, 0.4, 0.45}, {});
    box.pose.center = Eigen::Vector3d(range * std::cos(azimuth), range * std::sin(azimuth), 0.05);
    box.pose.axes = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix().transpose();
    std::size_t rings = 0;
    const PointList points = scan(box, seed, &rings);
    ASSERT_GE(rings, 5u) << "seed " << seed;
    const auto result = pipeline::recognize_cloud(points, cfg, "box");
    ASSERT_FALSE(result.objects.empty()) << "seed " << seed;
    const auto& o = nearest(result.objects, box.pose.center);
    EXPECT_TRUE(o.shape != "sphere" && o.shape != "cylinder" && o.shape != "cone" && o.shape != "frustum")
        << "seed " << seed << ": " << o.shape;
  }
}

}  // namespace
}  // namespace cloudshape
