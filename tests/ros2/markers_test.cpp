// MarkerArray from a recognition result: DELETEALL first, the solid's primitive with RViz's
// scales (diameters), TRIANGLE_LIST meshes, a label per object, the input's header everywhere.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "ros2/markers.hpp"
#include "ros2_test_support.hpp"

namespace cloudshape::ros2 {
namespace {

namespace mc = visualization_msgs::msg::Marker_Constants;

const io::RosHeader kHeader{{42, 7}, "lidar"};

pipeline::RecognitionResult every_shape() {
  pipeline::RecognitionResult r;
  r.source = "/points";
  r.objects = {test::object("box", {{"length", 3}, {"width", 2}, {"height", 1}}),
               test::object("sphere", {{"radius", 0.5}}),
               test::object("cylinder", {{"radius", 0.25}, {"height", 2}}),
               test::object("cone", {{"radius", 1}, {"height", 3}}),
               test::object("pentagonal_prism", {{"side", 1}, {"height", 2}}),
               test::object("tetrahedron", {{"edge", 2}})};
  r.objects[2].partial = true;
  pipeline::ObjectResult unknown;
  unknown.reason = "all points coplanar";
  r.objects.push_back(unknown);
  return r;
}

TEST(Ros2Markers, EveryShapeItsPrimitiveAndLabel) {
  config::Ros2Config style;
  style.circle_segments = 16;
  const visualization_msgs::msg::MarkerArray a = to_marker_array(every_shape(), kHeader, style);
  // DELETEALL, then solid and label for six solids, a label alone for the unknown object.
  ASSERT_EQ(a.markers().size(), 1u + 6 * 2 + 1);
  EXPECT_EQ(a.markers()[0].action(), mc::DELETEALL);
  EXPECT_EQ(a.markers()[0].ns(), "/points");
  for (const auto& m : a.markers()) {
    EXPECT_EQ(m.header().frame_id(), "lidar");
    EXPECT_EQ(m.header().stamp().sec(), 42);
    EXPECT_EQ(m.header().stamp().nanosec(), 7u);
    EXPECT_EQ(m.ns(), "/points");
  }
  const std::vector<std::int32_t> types = {mc::CUBE, mc::TEXT_VIEW_FACING, mc::SPHERE, mc::TEXT_VIEW_FACING,
                                           mc::CYLINDER, mc::TEXT_VIEW_FACING, mc::TRIANGLE_LIST,
                                           mc::TEXT_VIEW_FACING, mc::TRIANGLE_LIST, mc::TEXT_VIEW_FACING,
                                           mc::TRIANGLE_LIST, mc::TEXT_VIEW_FACING, mc::TEXT_VIEW_FACING};
  const std::vector<std::int32_t> ids = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 13};
  for (std::size_t i = 0; i < types.size(); ++i) {
    const auto& m = a.markers()[i + 1];
    EXPECT_EQ(m.type(), types[i]) << i;
    EXPECT_EQ(m.id(), ids[i]) << i;
    EXPECT_EQ(m.action(), mc::ADD) << i;
  }
  const auto scale = [&](std::size_t i) {
    const auto& s = a.markers()[i].scale();
    return Eigen::Vector3d(s.x(), s.y(), s.z());
  };
  EXPECT_LT((scale(1) - Eigen::Vector3d(3, 2, 1)).norm(), 1e-12);
  EXPECT_LT((scale(3) - Eigen::Vector3d(1, 1, 1)).norm(), 1e-12);      // sphere: diameter 1
  EXPECT_LT((scale(5) - Eigen::Vector3d(0.5, 0.5, 2)).norm(), 1e-12);  // cylinder: diameter, height
  EXPECT_EQ(a.markers()[7].points().size(), 3u * 2 * 16);             // cone: base and side, 16 segments
  EXPECT_EQ(a.markers()[9].points().size(), 3u * (2 * 3 + 2 * 5));     // prism: caps and 5 sides
  EXPECT_EQ(a.markers()[11].points().size(), 3u * 4);                  // tetrahedron: 4 faces
  EXPECT_EQ(a.markers()[2].text(), "box length 3 width 2 height 1 (87.5%)");
  EXPECT_EQ(a.markers()[6].text(), "partial cylinder radius 0.25 height 2 (87.5%)");
  EXPECT_EQ(a.markers()[13].text(), "unknown: all points coplanar");
  EXPECT_NEAR(a.markers()[2].scale().z(), style.label_height * 3.0, 1e-12);
  EXPECT_NEAR(a.markers()[13].scale().z(), style.label_fallback_height, 1e-12);
  EXPECT_FLOAT_EQ(a.markers()[1].color().a(), static_cast<float>(style.marker_alpha));
}

TEST(Ros2Markers, CylinderMarkerZIsTheSymmetryAxis) {
  pipeline::RecognitionResult r;
  r.objects = {test::object("cylinder", {{"radius", 1}, {"height", 4}})};
  const auto a = to_marker_array(r, kHeader, {});
  const auto& q = a.markers()[1].pose().orientation();
  const Eigen::Matrix3d m = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
  EXPECT_LT((m.col(2) - r.objects[0].axes.row(0).transpose()).norm(), 1e-9);
}

TEST(Ros2Markers, UnknownObjectIsItsExtentsEdgesAndItsLabel) {
  pipeline::RecognitionResult r;
  pipeline::ObjectResult unknown;
  unknown.reason = "no solid explains the points";
  unknown.extent.center = Eigen::Vector3d(1, 2, 3);
  unknown.extent.size = Eigen::Vector3d(4, 2, 1);
  r.objects = {unknown};
  config::Ros2Config style;
  const auto a = to_marker_array(r, kHeader, style);
  ASSERT_EQ(a.markers().size(), 3u);
  const auto& edges = a.markers()[1];
  EXPECT_EQ(edges.type(), mc::LINE_LIST);
  ASSERT_EQ(edges.points().size(), 24u);
  EXPECT_NEAR(edges.scale().x(), style.extent_line_width * 4.0, 1e-12);
  for (const auto& p : edges.points()) {  // every end on a corner of the 4 x 2 x 1 box
    EXPECT_NEAR(std::abs(p.x()), 2.0, 1e-12);
    EXPECT_NEAR(std::abs(p.y()), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(p.z()), 0.5, 1e-12);
  }
  EXPECT_DOUBLE_EQ(edges.pose().position().x(), 1.0);
  const auto& label = a.markers()[2];
  EXPECT_EQ(label.text(), "unknown: no solid explains the points");
  EXPECT_DOUBLE_EQ(label.pose().position().z(), 3.0);
  EXPECT_NEAR(label.scale().z(), style.label_height * 4.0, 1e-12);
}

TEST(Ros2Markers, NewShapesAreTriangleLists) {
  pipeline::RecognitionResult r;
  r.objects = {test::object("frustum", {{"radius", 2}, {"top_radius", 1}, {"height", 3}}),
               test::object("prism", {{"height", 2}, {"sides", 3}})};
  r.objects[1].polygon = {{0, 0}, {1, 0}, {0, 1}};
  config::Ros2Config style;
  style.circle_segments = 8;
  const auto a = to_marker_array(r, kHeader, style);
  ASSERT_EQ(a.markers().size(), 1u + 2 * 2);
  EXPECT_EQ(a.markers()[1].type(), mc::TRIANGLE_LIST);
  EXPECT_EQ(a.markers()[1].points().size(), 3u * 4 * 8);  // base, two per side, top
  EXPECT_EQ(a.markers()[3].type(), mc::TRIANGLE_LIST);
  EXPECT_EQ(a.markers()[3].points().size(), 3u * (2 + 2 * 3));
}

TEST(Ros2Markers, CloudWithoutObjectsOnlyClears) {
  const auto a = to_marker_array(pipeline::RecognitionResult{}, kHeader, {});
  ASSERT_EQ(a.markers().size(), 1u);
  EXPECT_EQ(a.markers()[0].action(), mc::DELETEALL);
}

}  // namespace
}  // namespace cloudshape::ros2
