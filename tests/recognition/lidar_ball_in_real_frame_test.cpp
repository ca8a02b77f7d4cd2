// The real SphereCalib lidar frame (shared/data/real/spherecalib) with its calibration ball moved:
// the ball's own returns taken out, a ball on a 2 cm pole scanned anew at another spot with the
// frame's own beams (16, every 2 degrees from -15 to 15; 0.19 degrees of azimuth; 1 cm range
// noise), a new return kept only where no real one on its beam is nearer, and the real returns
// behind the ball or its pole taken out. tools/lidar_moved_ball.py builds such frames in bulk.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "pipeline/recognize.hpp"
#include "shared_data.hpp"

namespace cloudshape {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBeams = 16;
constexpr double kLowestBeamDegrees = -15.0, kBeamStepDegrees = 2.0, kAzimuthStepDegrees = 0.19;
const Point kRealBall{1.723, 2.471, 0.009};  // SOURCES.md: the frame's own ball, radius 0.293 m

struct Ball {
  Point centre;
  double radius = 0.0;
};

// Along unit ray `d` from the sensor, the distance to the ball or to its pole (a vertical cylinder
// of 2 cm radius from the ball's bottom down to z = -1); infinity for a miss.
double ray_distance(const Eigen::Vector3d& d, const Ball& ball) {
  double t = std::numeric_limits<double>::infinity();
  const double along = d.dot(ball.centre);
  const double ball_disc = along * along - (ball.centre.squaredNorm() - ball.radius * ball.radius);
  if (ball_disc > 0.0 && along > 0.0) t = along - std::sqrt(ball_disc);
  // The pole's circle in the horizontal plane: |t d_xy - c_xy| = 0.02.
  const double pole_a = d.x() * d.x() + d.y() * d.y();
  const double pole_b = -2.0 * (d.x() * ball.centre.x() + d.y() * ball.centre.y());
  const double pole_c = ball.centre.x() * ball.centre.x() + ball.centre.y() * ball.centre.y() - 0.02 * 0.02;
  const double pole_disc = pole_b * pole_b - 4.0 * pole_a * pole_c;
  if (pole_a > 0.0 && pole_disc > 0.0) {
    const double pole_t = (-pole_b - std::sqrt(pole_disc)) / (2.0 * pole_a);
    const double z = pole_t * d.z();
    if (pole_t > 0.0 && z < ball.centre.z() - ball.radius && z > -1.0) t = std::min(t, pole_t);
  }
  return t;
}

// The beam (0-15) of an elevation, -1 off the frame's beams; the azimuth step of an azimuth.
int beam_of(double elevation_degrees) {
  const double beam = (elevation_degrees - kLowestBeamDegrees) / kBeamStepDegrees;
  const long nearest = std::lround(beam);
  return nearest >= 0 && nearest < kBeams && std::abs(beam - static_cast<double>(nearest)) < 0.25 ? static_cast<int>(nearest) : -1;
}
int azimuth_step_of(double azimuth_degrees) {
  return static_cast<int>(std::floor((azimuth_degrees + 180.0) / kAzimuthStepDegrees));
}

PointList frame_with(const PointList& real, const Ball& ball, std::uint64_t seed) {
  const int steps = static_cast<int>(std::ceil(360.0 / kAzimuthStepDegrees));
  // Per beam and azimuth step, the nearest real return (after the old ball is taken out).
  std::vector<double> nearest_real(static_cast<std::size_t>(kBeams * steps), std::numeric_limits<double>::infinity());
  PointList out;
  for (const Point& p : real) {
    if ((p - kRealBall).norm() <= 0.45) continue;
    const double range = p.norm();
    if (ray_distance(p / range, ball) < range) continue;  // behind the new ball or its pole
    out.push_back(p);
    const int beam = beam_of(std::atan2(p.z(), std::hypot(p.x(), p.y())) * 180.0 / kPi);
    const int step = azimuth_step_of(std::atan2(p.y(), p.x()) * 180.0 / kPi);
    if (beam < 0 || step < 0 || step >= steps) continue;
    double& nearest = nearest_real[static_cast<std::size_t>(beam * steps + step)];
    nearest = std::min(nearest, range);
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int beam = 0; beam < kBeams; ++beam) {
    const double elevation = (kLowestBeamDegrees + kBeamStepDegrees * beam) * kPi / 180.0;
    for (int step = 0; step < steps; ++step) {
      const double azimuth = (-180.0 + kAzimuthStepDegrees * step) * kPi / 180.0;
      const Eigen::Vector3d d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                              std::sin(elevation));
      const double t = ray_distance(d, ball);
      if (std::isfinite(t) && t < nearest_real[static_cast<std::size_t>(beam * steps + step)]) {
        out.push_back(d * (t + noise(rng)));
      }
    }
  }
  return out;
}

// Balls 2.3-3.6 m off, a few dozen nodes each of the scene's graph, whose voxel the 38 m frame
// sets: about the minimum an object needs (cfg.segment.min_object_nodes). Each must come out a
// sphere with issue 10's tolerances (radius within 5%, centre within 5 cm) and no other object
// within three radii of it.
TEST(LidarBallInRealFrame, ASmallBallAmongTheRealGroundAndWallsIsFound) {
  const auto path = testing::shared_data_path("real/spherecalib/example3_L1_S1_lidar_sphere.xyz");
  CLOUDSHAPE_REQUIRE_SHARED_DATA(path);
  const PointList real = io::read_cloud(path.string()).points;
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const Ball balls[] = {{{-2.0436, -1.0594, -0.0668}, 0.2548},
                        {{-3.0304, -1.0779, -0.2221}, 0.2905},
                        {{2.3235, 2.7627, 0.2986}, 0.2642}};
  std::uint64_t seed = 1;
  for (const Ball& ball : balls) {
    const auto result = pipeline::recognize_cloud(frame_with(real, ball, seed++), cfg, "moved ball");
    const auto nearest = std::min_element(result.objects.begin(), result.objects.end(), [&](const auto& a, const auto& b) {
      return (a.center - ball.centre).norm() < (b.center - ball.centre).norm();
    });
    ASSERT_NE(nearest, result.objects.end());
    const std::string where = "ball at " + std::to_string(ball.centre.norm()) + " m";
    EXPECT_EQ(nearest->shape, "sphere") << where;
    if (nearest->shape != "sphere" || nearest->dimensions.empty()) continue;
    EXPECT_NEAR(nearest->dimensions.front().second, ball.radius, 0.05 * ball.radius) << where;
    EXPECT_LE((nearest->center - ball.centre).norm(), 0.05) << where;
    const auto near = std::count_if(result.objects.begin(), result.objects.end(), [&](const auto& o) {
      return (o.center - ball.centre).norm() < 3.0 * ball.radius;
    });
    EXPECT_EQ(near, 1) << where;
  }
}

// Balls 4.5-5.3 m off on three beams, 69-97 returns (tools/lidar_moved_ball.py --seed 7: balls 3,
// 11, 15, 27): a few dozen points of a coarse voxel, their segment is segmented again alone, where
// a voxel holds two or three returns: the ball's part there is an object when it holds
// cfg.segment.min_object_nodes points. At least 3 of the 4 found (measured 4; 1 here and none of
// the tool's four when the part needed that many nodes).
TEST(LidarBallInRealFrame, AFarBallOnThreeBeamsIsFound) {
  const auto path = testing::shared_data_path("real/spherecalib/example3_L1_S1_lidar_sphere.xyz");
  CLOUDSHAPE_REQUIRE_SHARED_DATA(path);
  const PointList real = io::read_cloud(path.string()).points;
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const Ball balls[] = {{{-3.5545, 2.7323, -0.0160}, 0.2532},
                        {{3.7880, 3.6139, -0.1497}, 0.3042},
                        {{-0.7595, 4.6094, -0.1144}, 0.3211},
                        {{5.3022, 0.4049, -0.0356}, 0.2573}};
  std::uint64_t seed = 11;
  int found = 0;
  for (const Ball& ball : balls) {
    const auto result =
        pipeline::recognize_cloud(frame_with(real, ball, seed++), cfg, "moved ball");
    const auto nearest = std::min_element(
        result.objects.begin(), result.objects.end(), [&](const auto& a, const auto& b) {
          return (a.center - ball.centre).norm() < (b.center - ball.centre).norm();
        });
    if (nearest == result.objects.end() || nearest->shape != "sphere" ||
        nearest->dimensions.empty())
      continue;
    const auto near = std::count_if(
        result.objects.begin(), result.objects.end(),
        [&](const auto& o) { return (o.center - ball.centre).norm() < 3.0 * ball.radius; });
    found += std::abs(nearest->dimensions.front().second - ball.radius) <= 0.05 * ball.radius &&
             (nearest->center - ball.centre).norm() <= 0.05 && near == 1;
  }
  EXPECT_GE(found, 3);
}

}  // namespace
}  // namespace cloudshape
