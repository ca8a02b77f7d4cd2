// A lidar object's own noise, read along its scan lines, and how far its points scatter about a
// solid: the right solid leaves them within their noise, a wrong one passing near most of them
// does not.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lidar_frames.hpp"
#include "pipeline/scan_fit.hpp"
#include "synth/range_sensor.hpp"
#include "synth/scene.hpp"

namespace cloudshape {
namespace {

// A ball of radius 0.3 m, 4 m off, seen by the SphereCalib frame's lidar with `noise` of range
// noise: its finite returns.
PointList scanned_ball(double noise, std::uint64_t seed) {
  synth::Scene scene;
  synth::SolidSpec ball = synth::make_solid(synth::ShapeKind::sphere, {0.3}, {});
  ball.pose.center = Eigen::Vector3d(4.0, 0.3, 0.1);
  scene.objects.push_back({ball, 20});
  std::mt19937_64 rng(seed);
  PointList points;
  for (const Point& p :
       synth::render(scene, testing::spherecalib_lidar(noise), synth::SensorPose{}, rng).points)
    if (p.allFinite()) points.push_back(p);
  return points;
}

pipeline::FittedSolid sphere(const Point& centre, double radius) {
  pipeline::FittedSolid s;
  s.shape = pipeline::Shape::sphere;
  s.center = centre;
  s.signed_distance = [centre, radius](const Point& p) { return (p - centre).norm() - radius; };
  return s;
}

// Returns on a flat wall 4 m off, every 0.2 degrees on 16 rings 2 degrees apart, with `noise` of
// range noise.
PointList scanned_wall(double noise, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  PointList points;
  for (int ring = 0; ring < 16; ++ring) {
    for (int step = -100; step <= 100; ++step) {
      const double elevation = (-15.0 + 2.0 * ring) * kDegree, azimuth = 0.2 * step * kDegree;
      const Eigen::Vector3d beam(std::cos(elevation) * std::cos(azimuth),
                                 std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
      points.push_back((4.0 / beam.x() + noise * gauss(rng)) * beam);
    }
  }
  return points;
}

// On a flat wall the neighbours along a ring give the range noise: within 10% of the drawn
// deviation for 0.5, 1 and 2 cm.
TEST(ScanFit, NoiseAlongTheRingsIsTheRangeNoise) {
  for (double noise : {0.005, 0.01, 0.02}) {
    EXPECT_NEAR(pipeline::scan_line_noise(scanned_wall(noise, 3), Point::Zero()), noise,
                0.1 * noise)
        << noise;
  }
}

// On a ball 0.3 m across 4 m off, the range bends fast near its outline, where the rings meet it
// obliquely: the measure reads the noise and that bend, up to 40% more than the noise.
TEST(ScanFit, ARoundObjectsOutlineAddsItsBend) {
  for (double noise : {0.005, 0.01, 0.02}) {
    const PointList points = scanned_ball(noise, 3);
    ASSERT_GT(points.size(), 100u);
    const double measured = pipeline::scan_line_noise(points, Point::Zero());
    EXPECT_GE(measured, noise) << noise;
    EXPECT_LE(measured, 1.4 * noise) << noise;
  }
}

// About the ball itself the points scatter by their noise, less where the beams meet the ball
// obliquely (the noise is along the beam: between half and all of it); about a sphere a tenth
// smaller, which still passes within 3 cm of the front of it, by several times the noise.
TEST(ScanFit, ScatterAboutTheRightSolidIsTheNoise) {
  const PointList points = scanned_ball(0.01, 4);
  const double noise = pipeline::scan_line_noise(points, Point::Zero());
  const Point centre(4.0, 0.3, 0.1);
  const double right = pipeline::scatter_about(points, sphere(centre, 0.3));
  EXPECT_GT(right, 0.5 * noise);
  EXPECT_LT(right, noise);
  EXPECT_GT(pipeline::scatter_about(points, sphere(centre + Eigen::Vector3d(0.03, 0.0, 0.0), 0.27)),
            3.0 * noise);
}

// Noise-free returns on the wall: the range a point's neighbours give at its direction is its own
// within the range's bend over one step (4 m x (0.2 degrees)^2 / 2: 25 micrometres).
TEST(ScanFit, NoNoiseOnAFlatWall) {
  EXPECT_LT(pipeline::scan_line_noise(scanned_wall(0.0, 1), Point::Zero()), 5e-5);
}

// Too few points to have neighbours either side: no noise is measured.
TEST(ScanFit, TwoPointsHaveNoNoise) {
  const PointList points{Point(1, 0, 0), Point(1, 0.01, 0)};
  EXPECT_EQ(pipeline::scan_line_noise(points, Point::Zero()), 0.0);
}

}  // namespace
}  // namespace cloudshape
