// Detection3DArray from a recognition result: class_id and score, the solid's pose as a unit
// quaternion of its axes, the solid's own box, the input's header on every detection.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "ros2/detections.hpp"
#include "ros2_test_support.hpp"

namespace cloudshape::ros2 {
namespace {

constexpr double kTol = 1e-12;

const io::RosHeader kHeader{{1700000000, 123456789}, "camera_depth_optical_frame"};

Eigen::Matrix3d rotation_of(const geometry_msgs::msg::Quaternion& q) {
  const Eigen::Quaterniond e(q.w(), q.x(), q.y(), q.z());
  EXPECT_NEAR(e.norm(), 1.0, kTol);
  return e.toRotationMatrix();
}

Eigen::Vector3d position_of(const geometry_msgs::msg::Point& p) { return {p.x(), p.y(), p.z()}; }

void expect_header(const std_msgs::msg::Header& h) {
  EXPECT_EQ(h.stamp().sec(), kHeader.stamp.sec);
  EXPECT_EQ(h.stamp().nanosec(), kHeader.stamp.nanosec);
  EXPECT_EQ(h.frame_id(), kHeader.frame_id);
}

pipeline::RecognitionResult two_objects() {
  pipeline::RecognitionResult r;
  r.source = "/camera/depth/points";
  r.objects.push_back(test::object("box", {{"length", 30}, {"width", 20}, {"height", 10}}));
  r.objects.push_back(test::object("cone", {{"radius", 3}, {"height", 8}}));
  r.objects[1].center = Eigen::Vector3d(-1, 0.5, 2);
  r.objects[1].confidence = 0.5;
  return r;
}

TEST(Ros2Detections, OnePerObjectWithShapeScorePoseAndBox) {
  const pipeline::RecognitionResult r = two_objects();
  const vision_msgs::msg::Detection3DArray a = to_detection_array(r, kHeader);
  expect_header(a.header());
  ASSERT_EQ(a.detections().size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const vision_msgs::msg::Detection3D& d = a.detections()[i];
    expect_header(d.header());
    EXPECT_EQ(d.id(), std::to_string(i));
    ASSERT_EQ(d.results().size(), 1u);
    EXPECT_EQ(d.results()[0].hypothesis().class_id(), r.objects[i].shape);
    EXPECT_DOUBLE_EQ(d.results()[0].hypothesis().score(), r.objects[i].confidence);
    const geometry_msgs::msg::Pose& pose = d.results()[0].pose().pose();
    EXPECT_LT((position_of(pose.position()) - r.objects[i].center).norm(), kTol);
    EXPECT_LT((rotation_of(pose.orientation()) - r.objects[i].axes.transpose()).norm(), 1e-9);
    for (double c : d.results()[0].pose().covariance()) EXPECT_EQ(c, 0.0);
    EXPECT_LT((rotation_of(d.bbox().center().orientation()) - r.objects[i].axes.transpose()).norm(), 1e-9);
  }
  const auto& box = a.detections()[0].bbox();
  EXPECT_NEAR(box.size().x(), 30, kTol);
  EXPECT_NEAR(box.size().y(), 20, kTol);
  EXPECT_NEAR(box.size().z(), 10, kTol);
  EXPECT_LT((position_of(box.center().position()) - r.objects[0].center).norm(), kTol);
  // The cone's box is centred half its height above its base (pose.center).
  const auto& cone = a.detections()[1].bbox();
  EXPECT_NEAR(cone.size().x(), 8, 1e-9);
  EXPECT_NEAR(cone.size().y(), 6, 1e-9);
  EXPECT_NEAR(cone.size().z(), 6, 1e-9);
  const Eigen::Vector3d expected = r.objects[1].center + 4.0 * r.objects[1].axes.row(0).transpose();
  EXPECT_LT((position_of(cone.center().position()) - expected).norm(), 1e-9);
}

TEST(Ros2Detections, ErrorResultIsOneUnknownOfNoSize) {
  pipeline::RecognitionResult r;
  r.source = "/camera/depth/points";
  pipeline::ObjectResult unknown;
  unknown.reason = "ingest: no field named 'z'";
  r.objects.push_back(unknown);
  const vision_msgs::msg::Detection3DArray a = to_detection_array(r, kHeader);
  ASSERT_EQ(a.detections().size(), 1u);
  EXPECT_EQ(a.detections()[0].results()[0].hypothesis().class_id(), "unknown");
  EXPECT_EQ(a.detections()[0].results()[0].hypothesis().score(), 0.0);
  EXPECT_EQ(a.detections()[0].bbox().size().x(), 0.0);
  EXPECT_EQ(a.detections()[0].bbox().center().orientation().w(), 1.0);
  expect_header(a.detections()[0].header());
}

TEST(Ros2Detections, UnknownObjectsBoxIsItsExtent) {
  pipeline::RecognitionResult r;
  pipeline::ObjectResult unknown;
  unknown.extent.center = Eigen::Vector3d(-1, 0.5, 2);
  unknown.extent.axes = test::test_rotation().transpose();
  unknown.extent.size = Eigen::Vector3d(0.3, 0.2, 0.1);
  r.objects.push_back(unknown);
  const vision_msgs::msg::Detection3DArray a = to_detection_array(r, kHeader);
  ASSERT_EQ(a.detections().size(), 1u);
  const auto& d = a.detections()[0];
  EXPECT_NEAR(d.bbox().size().x(), 0.3, 1e-15);
  EXPECT_NEAR(d.bbox().size().z(), 0.1, 1e-15);
  EXPECT_LT((position_of(d.bbox().center().position()) - unknown.extent.center).norm(), kTol);
  EXPECT_LT((rotation_of(d.bbox().center().orientation()) - test::test_rotation()).norm(), 1e-9);
}

TEST(Ros2Detections, CloudWithoutObjectsIsAnEmptyArray) {
  pipeline::RecognitionResult r;
  const vision_msgs::msg::Detection3DArray a = to_detection_array(r, kHeader);
  EXPECT_TRUE(a.detections().empty());
  expect_header(a.header());
}

}  // namespace
}  // namespace cloudshape::ros2
