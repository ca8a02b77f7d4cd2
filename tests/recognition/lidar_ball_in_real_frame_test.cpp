// The real SphereCalib lidar frame (shared/data/real/spherecalib) with its calibration ball moved:
// the ball's own returns taken out, a ball on a 2 cm pole scanned anew at another spot with the
// frame's own beams (16, every 2 degrees from -15 to 15; 0.19 degrees of azimuth; 1 cm range
// noise), and the real returns it shadows taken out. The ball must be found wherever it stands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "pipeline/recognize.hpp"
#include "shared_data.hpp"

namespace cloudshape {
namespace {

constexpr double kPi = 3.14159265358979323846;
const Point kRealBall{1.723, 2.471, 0.009};  // SOURCES.md: the frame's own ball, r = 0.293 m

struct Ball {
  Point centre;
  double radius = 0.0;
};

// The distance along unit ray `d` from the origin to the ball or its pole (a vertical cylinder of
// 2 cm radius from the ball's bottom down to z = -1), infinity for a miss.
double hit(const Eigen::Vector3d& d, const Ball& ball) {
  double t = std::numeric_limits<double>::infinity();
  const double b = d.dot(ball.centre);
  const double disc = b * b - (ball.centre.squaredNorm() - ball.radius * ball.radius);
  if (disc > 0.0 && b > 0.0) t = b - std::sqrt(disc);
  const double a = d.x() * d.x() + d.y() * d.y();
  const double bb = -2.0 * (d.x() * ball.centre.x() + d.y() * ball.centre.y());
  const double cc = ball.centre.x() * ball.centre.x() + ball.centre.y() * ball.centre.y() - 0.02 * 0.02;
  const double disc2 = bb * bb - 4.0 * a * cc;
  if (a > 0.0 && disc2 > 0.0) {
    const double t2 = (-bb - std::sqrt(disc2)) / (2.0 * a);
    const double z = t2 * d.z();
    if (t2 > 0.0 && z < ball.centre.z() - ball.radius && z > -1.0) t = std::min(t, t2);
  }
  return t;
}

PointList frame_with(const PointList& real, const Ball& ball, std::uint64_t seed) {
  PointList out;
  for (const Point& p : real) {
    if ((p - kRealBall).norm() <= 0.45) continue;
    // A return behind the ball along its own ray is in the ball's shadow.
    const Eigen::Vector3d u = p.normalized();
    const double b = u.dot(ball.centre);
    const double disc = b * b - (ball.centre.squaredNorm() - ball.radius * ball.radius);
    if (disc > 0.0 && b > 0.0 && p.norm() > b) continue;
    out.push_back(p);
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int beam = 0; beam < 16; ++beam) {
    const double elevation = (-15.0 + 2.0 * beam) * kPi / 180.0;
    for (int step = 0; step * 0.19 < 360.0; ++step) {
      const double azimuth = (-180.0 + 0.19 * step) * kPi / 180.0;
      const Eigen::Vector3d d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                              std::sin(elevation));
      const double t = hit(d, ball);
      if (std::isfinite(t)) out.push_back(d * (t + noise(rng)));
    }
  }
  return out;
}

// Balls 2.3-3.6 m away, each a few dozen nodes of the scene's graph (its voxel set by the 38 m
// frame), about as many as an object needs (cfg.segment.min_object_nodes). Before segments under
// that were tried at their own resolution too, the two farther were not found (an unknown scrap;
// nothing within 1.4 m). Tolerances of issue 10: radius within 5%, centre within 5 cm, and no
// other object within three radii.
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

}  // namespace
}  // namespace cloudshape
