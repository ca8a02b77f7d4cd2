// Cameras and views: where points land in a panel, and how each camera is placed.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "render/cameras.hpp"
#include "render/view.hpp"

namespace cloudshape::render {
namespace {

constexpr double kTol = 1e-9;

TEST(View, SensorCameraIsAPinholeAtTheOriginLookingAlongZ) {
  View view;
  view.camera = sensor_camera();
  view.scale = 100.0;
  view.offset = {300.0, 200.0};
  const auto px = view.pixel({1.0, 2.0, 4.0});
  ASSERT_TRUE(px.has_value());
  EXPECT_NEAR(px->x(), 300.0 + 25.0, kTol);
  EXPECT_NEAR(px->y(), 200.0 + 50.0, kTol);
  EXPECT_NEAR(px->z(), 4.0, kTol);
  EXPECT_FALSE(view.pixel({1.0, 2.0, -4.0}).has_value());
  EXPECT_FALSE(view.segment({0, 0, -1}, {1, 1, -2}).has_value());
  // A segment from behind the camera to in front keeps its visible end.
  const auto s = view.segment({0.5, 0.0, -1.0}, {0.5, 0.0, 1.0});
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(s->second.x(), 300.0 + 50.0, kTol);
}

TEST(View, FitViewFillsThePanelLessItsMargin) {
  // A 4 x 2 rectangle of points at z = 10 seen by an orthographic camera: the width decides.
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 20; ++j) points.emplace_back(-2.0 + 0.1 * i, -1.0 + 0.1 * j, 10.0);
  Camera ortho{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), false};
  const PixelRect rect{100.0, 50.0, 600.0, 400.0};
  const View view = fit_view(ortho, points, {}, rect, 20.0);
  // Every row and column holds many points, so the 1st and 99th percentiles are the extremes:
  // 4 units wide across 560 pixels.
  EXPECT_NEAR(view.scale, 560.0 / 4.0, 1e-6);
  const auto middle = view.pixel({0.0, 0.0, 10.0});
  ASSERT_TRUE(middle.has_value());
  EXPECT_NEAR(middle->x(), 400.0, 1e-6);
  EXPECT_NEAR(middle->y(), 250.0, 1e-6);
  const auto corner = view.pixel({-2.0, -1.0, 10.0});
  EXPECT_TRUE(rect.contains(corner->head<2>()));
}

TEST(View, FitViewWidensForAWireframeButAtMostTwice) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= 100; ++i) points.emplace_back(-1.0 + 0.02 * i, 0.0, 5.0);
  Camera ortho{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), false};
  const PixelRect rect{0.0, 0.0, 1000.0, 1000.0};
  const View tight = fit_view(ortho, points, {}, rect, 0.0);
  const View wide = fit_view(ortho, points, {{-1.5, 0.0, 5.0}, {1.5, 0.0, 5.0}}, rect, 0.0);
  const View capped = fit_view(ortho, points, {{-100.0, 0.0, 5.0}, {100.0, 0.0, 5.0}}, rect, 0.0);
  EXPECT_NEAR(tight.scale, 1000.0 / 1.96, 1e-6);
  EXPECT_NEAR(wide.scale, 1000.0 / 3.0, 1e-6);
  EXPECT_NEAR(capped.scale, 1000.0 / (2.0 * 1.96), 1e-6);
}

TEST(Cameras, ObliqueCameraTurnsAboutThePivotAndStaysARotation) {
  const Camera base = sensor_camera();
  const Eigen::Vector3d pivot(0.1, 0.2, 2.0);
  const Camera same = oblique_camera(base, pivot, 0.0, 0.0);
  EXPECT_TRUE(same.rotation.isApprox(Eigen::Matrix3d::Identity(), kTol));
  const Camera turned = oblique_camera(base, pivot, 40.0, 30.0);
  EXPECT_TRUE((turned.rotation * turned.rotation.transpose()).isApprox(Eigen::Matrix3d::Identity(), kTol));
  EXPECT_NEAR(turned.rotation.determinant(), 1.0, kTol);
  const Eigen::Vector3d forward = turned.rotation.row(2).transpose();
  // Looking down (towards +y, the sensor's down) by the elevation, and to the left by the azimuth.
  EXPECT_NEAR(std::asin(forward.y()), 30.0 * M_PI / 180.0, 1e-9);
  EXPECT_NEAR(std::atan2(-forward.x(), forward.z()), 40.0 * M_PI / 180.0, 1e-9);
  EXPECT_FALSE(turned.perspective);
  EXPECT_TRUE(turned.toward_viewer(pivot).isApprox(-forward, kTol));
}

TEST(Cameras, PrincipalAxesCameraLooksAcrossAFlatCloudFromTheOriginsSide) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 2000; ++i) points.emplace_back(3.0 * u(rng), 1.0 * u(rng), -5.0 + 0.01 * u(rng));
  const Camera c = principal_axes_camera(points, Eigen::Vector3d::Zero());
  const Camera from_below = principal_axes_camera(points, Eigen::Vector3d(0.0, 0.0, -50.0));
  EXPECT_FALSE(c.perspective);
  const Eigen::Vector3d right = c.rotation.row(0).transpose(), forward = c.rotation.row(2).transpose();
  EXPECT_GT(std::abs(right.x()), 0.99);     // the longest spread across the picture
  EXPECT_NEAR(forward.z(), -1.0, 1e-3);      // the cloud is at z = -5: seen from the origin's side
  EXPECT_NEAR(c.rotation.determinant(), 1.0, kTol);
  EXPECT_NEAR(from_below.rotation(2, 2), 1.0, 1e-3);  // seen from the other side when asked
}

}  // namespace
}  // namespace cloudshape::render
