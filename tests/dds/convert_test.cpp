// Round trips core -> IDL -> core through common/dds/convert.hpp must be the identity:
// the services rely on it to compute exactly what the in-process chain computes.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "../pipeline/stage_fixtures.hpp"
#include "corrupt_sample.hpp"
#include "dds/checked_type.hpp"
#include "dds/convert.hpp"
#include "dds/ingest_sample.hpp"
#include "dds/result_joiner.hpp"
#include "dds/topics.hpp"
#include "io/cloud_reader.hpp"
#include "pipeline/solve.hpp"

namespace cloudshape::dds {
namespace {

using pipeline::testing::StagedCloud;

const StagedCloud& box() {
  static const StagedCloud s = pipeline::testing::stage(synth::ShapeKind::box, {3.0, 2.0, 1.0});
  return s;
}

TEST(DdsConvert, CloudRoundTripIsExact) {
  const pipeline::PreprocessedCloud& pre = box().pre;
  const msg::CloudData m = to_msg(pre, 12345);
  EXPECT_EQ(m.points_in(), 12345u);
  const pipeline::PreprocessedCloud back = from_msg(m);
  ASSERT_EQ(back.points.size(), pre.points.size());
  for (std::size_t i = 0; i < pre.points.size(); ++i) ASSERT_EQ(back.points[i], pre.points[i]);
  EXPECT_EQ(back.resolution, pre.resolution);
  EXPECT_EQ(back.voxel_size, pre.voxel_size);
  EXPECT_EQ(back.outliers_removed, pre.outliers_removed);
}

TEST(DdsConvert, ViewpointCrossesTheWireOnlyWhenKnown) {
  msg::CloudData m = to_msg(box().pre, 1);
  set_viewpoint(m, std::nullopt);
  EXPECT_FALSE(viewpoint_of(m).has_value());
  set_viewpoint(m, Point(0.25, -1.5, 3.0));
  const std::optional<Point> back = viewpoint_of(m);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, Point(0.25, -1.5, 3.0));
}

TEST(DdsConvert, XyzRejectsAPartialPoint) {
  EXPECT_THROW(from_xyz({1.0, 2.0}), std::invalid_argument);
}

// What ingest hands to object_clouds for a cloud cloudshape-inject published: to_raw_cloud, CDR
// as the service's reader decodes it, then ingest's sample checks.
RawCloudPoints over_the_wire(const PointList& points, const GridLayout& grid) {
  msg::RawCloud sent = to_raw_cloud(points, grid);
  sent.header().source("frame.pcd");
  const auto payload = cloudshape::testing::serialized<msg::RawCloudPubSubType>(sent);
  msg::RawCloud received;
  CheckedPubSubType<decltype(topics::raw_cloud)> type;
  EXPECT_TRUE(type.deserialize(payload.get(), &received));
  EXPECT_FALSE(received.header().error()) << received.header().error_text();
  return raw_cloud_points(received, config::InputConfig{});
}

void expect_bit_identical(const RawCloudPoints& got, const PointList& points, const GridLayout& grid) {
  ASSERT_EQ(got.points.size(), points.size());
  EXPECT_EQ(got.non_finite_dropped, 0u);
  EXPECT_EQ(std::memcmp(got.points.data(), points.data(), points.size() * sizeof(Point)), 0);
  EXPECT_EQ(got.grid.organized(), grid.organized());
  EXPECT_EQ(got.grid.width, grid.width);
  EXPECT_EQ(got.grid.height, grid.height);
  EXPECT_EQ(got.grid.pixel, grid.pixel);
}

TEST(DdsConvert, AnOrganizedCloudReachesIngestWithItsGrid) {
  GridLayout grid{200, 150, {}};
  const PointList& points = box().pre.points;
  ASSERT_LT(2 * points.size(), grid.width * grid.height);
  for (std::uint32_t i = 0; i < points.size(); ++i) grid.pixel.push_back(2 * i + 1);
  const msg::RawCloud m = to_raw_cloud(points, grid);
  EXPECT_EQ(m.width(), 200u);
  EXPECT_EQ(m.height(), 150u);
  expect_bit_identical(over_the_wire(points, grid), points, grid);
}

// Real Kinect frames (640 x 480, NaN pixels absent): the grid that reaches object_clouds in
// ingest is the file's, pixel for pixel, as cloudshape-recognize passes it.
TEST(DdsConvert, RealOrganizedFramesReachIngestBitIdentical) {
  for (const char* name : {"learn0.pcd", "learn33.pcd"}) {
    const std::filesystem::path path = std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real/mosd_learn" / name;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not present";
    SCOPED_TRACE(name);
    const io::CloudFile file = io::read_cloud(path.string());
    ASSERT_TRUE(file.grid.organized());
    EXPECT_EQ(file.grid.width, 640u);
    EXPECT_EQ(file.grid.height, 480u);
    ASSERT_LT(file.points.size(), 640u * 480u);  // holes: the pixels are not simply 0, 1, 2, ...
    expect_bit_identical(over_the_wire(file.points, file.grid), file.points, file.grid);
  }
}

TEST(DdsConvert, AnUnorganizedCloudTravelsWithoutALayout) {
  const PointList& points = box().pre.points;
  const msg::RawCloud m = to_raw_cloud(points, GridLayout{});
  EXPECT_EQ(m.width(), 0u);
  EXPECT_EQ(m.height(), 0u);
  EXPECT_TRUE(m.pixel().empty());
  expect_bit_identical(over_the_wire(points, GridLayout{}), points, GridLayout{});
}

TEST(DdsConvert, PlanesRoundTripIsExact) {
  const pipeline::PlaneSegmentation& s = box().planes;
  ASSERT_FALSE(s.planes.empty());
  const pipeline::PlaneSegmentation back = from_msg(to_msg(s));
  ASSERT_EQ(back.planes.size(), s.planes.size());
  for (std::size_t i = 0; i < s.planes.size(); ++i) {
    EXPECT_EQ(back.planes[i].plane.normal, s.planes[i].plane.normal);
    EXPECT_EQ(back.planes[i].plane.offset, s.planes[i].plane.offset);
    EXPECT_EQ(back.planes[i].inliers, s.planes[i].inliers);
    EXPECT_EQ(back.planes[i].boundary, s.planes[i].boundary);
    EXPECT_EQ(back.planes[i].is_face, s.planes[i].is_face);
    EXPECT_EQ(back.planes[i].curvature_sagitta, s.planes[i].curvature_sagitta);
  }
  ASSERT_EQ(back.lines.size(), s.lines.size());
  for (std::size_t i = 0; i < s.lines.size(); ++i) {
    EXPECT_EQ(back.lines[i].line.point, s.lines[i].line.point);
    EXPECT_EQ(back.lines[i].line.direction, s.lines[i].line.direction);
    EXPECT_EQ(back.lines[i].t_min, s.lines[i].t_min);
    EXPECT_EQ(back.lines[i].t_max, s.lines[i].t_max);
    EXPECT_EQ(back.lines[i].plane_a, s.lines[i].plane_a);
    EXPECT_EQ(back.lines[i].plane_b, s.lines[i].plane_b);
  }
  EXPECT_EQ(back.labels, s.labels);
  pipeline::PlaneSegmentation seen = s;
  seen.view_noise = 0.0031;  // read in a depth camera's view: the solver reuses it
  EXPECT_EQ(from_msg(to_msg(seen)).view_noise, seen.view_noise);
}

TEST(DdsConvert, KeypointsRoundTripIsExact) {
  const pipeline::KeypointSet& k = box().keypoints;
  ASSERT_FALSE(k.keypoints.empty());
  const pipeline::KeypointSet back = from_msg(to_msg(k));
  EXPECT_EQ(back.reference.center, k.reference.center);
  EXPECT_EQ(back.reference.radius, k.reference.radius);
  ASSERT_EQ(back.keypoints.size(), k.keypoints.size());
  for (std::size_t i = 0; i < k.keypoints.size(); ++i) {
    EXPECT_EQ(back.keypoints[i].index, k.keypoints[i].index);
    EXPECT_EQ(back.keypoints[i].neighbourhood, k.keypoints[i].neighbourhood);
  }
}

TEST(DdsConvert, ClassificationRoundTripIsExact) {
  pipeline::Classification c = box().classification;
  c.reason = "a reason";
  c.candidates = {pipeline::Shape::box, pipeline::Shape::cylinder, pipeline::Shape::unknown};
  c.cap_plane = 3;
  c.cap_outline = {pipeline::OutlineKind::circle, Point(0.25, -1.5, 2.0), 0.125, 0.03, 0.78, 0.01};
  c.rectangular_face = true;
  const pipeline::Classification back = from_msg(to_msg(c));
  ASSERT_EQ(back.keypoints.size(), c.keypoints.size());
  for (std::size_t i = 0; i < c.keypoints.size(); ++i) {
    EXPECT_EQ(back.keypoints[i].index, c.keypoints[i].index);
    EXPECT_EQ(back.keypoints[i].type, c.keypoints[i].type);
    EXPECT_EQ(back.keypoints[i].curvature, c.keypoints[i].curvature);
    EXPECT_EQ(back.keypoints[i].gap_degrees, c.keypoints[i].gap_degrees);
  }
  EXPECT_EQ(back.counts.corner, c.counts.corner);
  EXPECT_EQ(back.counts.edge, c.counts.edge);
  EXPECT_EQ(back.counts.border, c.counts.border);
  EXPECT_EQ(back.shape, c.shape);
  EXPECT_EQ(back.candidates, c.candidates);
  EXPECT_EQ(back.reason, c.reason);
  EXPECT_EQ(back.face_fraction, c.face_fraction);
  EXPECT_EQ(back.sphere_test, c.sphere_test);
  EXPECT_EQ(back.cap_plane, c.cap_plane);
  EXPECT_EQ(back.cap_outline.kind, c.cap_outline.kind);
  EXPECT_EQ(back.cap_outline.center, c.cap_outline.center);
  EXPECT_EQ(back.cap_outline.radius, c.cap_outline.radius);
  EXPECT_EQ(back.cap_outline.circle_rms, c.cap_outline.circle_rms);
  EXPECT_EQ(back.cap_outline.rect_fill, c.cap_outline.rect_fill);
  EXPECT_EQ(back.cap_outline.polygon_harmonic, c.cap_outline.polygon_harmonic);
  EXPECT_EQ(back.rectangular_face, c.rectangular_face);
  c.cap_plane.reset();
  EXPECT_FALSE(from_msg(to_msg(c)).cap_plane);
}

TEST(DdsConvert, EveryShapeNameComesBack) {
  for (pipeline::Shape s : pipeline::kNamedShapes) EXPECT_EQ(shape_from_name(pipeline::shape_name(s)), s);
  EXPECT_EQ(shape_from_name("no such shape"), pipeline::Shape::unknown);
}

TEST(DdsConvert, ResultRoundTripIsExact) {
  const StagedCloud& s = box();
  const config::PipelineConfig cfg;
  const pipeline::ObjectResult o = pipeline::solve_object(s.pre.points, s.planes, s.keypoints,
                                                          s.classification, s.pre.resolution, cfg.solve);
  msg::ShapeResult m;
  m.header().source("box.pcd");
  m.header().timings().planes_ms(2.5);
  m.header().timings().solve_ms(0.5);
  m.points_in(20000);
  m.points_used(s.pre.points.size());
  m.resolution(s.pre.resolution);
  m.objects().push_back(to_msg(o));
  const pipeline::RecognitionResult r = to_recognition_result(m);
  EXPECT_EQ(r.source, "box.pcd");
  EXPECT_EQ(r.points_in, 20000u);
  EXPECT_EQ(r.points_used, s.pre.points.size());
  EXPECT_EQ(r.resolution, s.pre.resolution);
  EXPECT_EQ(r.timings.total_ms, 3.0);
  ASSERT_EQ(r.objects.size(), 1u);
  const pipeline::ObjectResult& b = r.objects[0];
  EXPECT_EQ(b.shape, o.shape);
  EXPECT_EQ(b.confidence, o.confidence);
  EXPECT_EQ(b.dimensions, o.dimensions);
  EXPECT_EQ(b.center, o.center);
  EXPECT_EQ(b.axes, o.axes);
  EXPECT_EQ(b.partial, o.partial);
  EXPECT_EQ(b.keypoints.corner, o.keypoints.corner);
  EXPECT_EQ(b.keypoints.edge, o.keypoints.edge);
  EXPECT_EQ(b.keypoints.border, o.keypoints.border);
  EXPECT_EQ(b.reason, o.reason);
  EXPECT_EQ(b.extent.center, o.extent.center);
  EXPECT_EQ(b.extent.axes, o.extent.axes);
  EXPECT_EQ(b.extent.size, o.extent.size);
  EXPECT_GT(o.extent.size.minCoeff(), 0.0);
}

// The shape-specific extras travel too: a prism's polygon, a tetrahedron's corners.
TEST(DdsConvert, PolygonVerticesAndRegularRoundTrip) {
  pipeline::ObjectResult o;
  o.shape = "prism";
  o.polygon = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.25}};
  o.vertices = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.5}};
  o.regular = true;
  o.extent.size = {3.0, 2.0, 1.0};
  const pipeline::ObjectResult b = from_msg(to_msg(o));
  EXPECT_EQ(b.polygon, o.polygon);
  EXPECT_EQ(b.vertices, o.vertices);
  EXPECT_TRUE(b.regular);
  EXPECT_EQ(b.extent.size, o.extent.size);
}

}  // namespace
}  // namespace cloudshape::dds

namespace cloudshape::dds {
namespace {

msg::ShapeResult object_result(std::uint32_t index, std::uint32_t count, const std::string& shape) {
  msg::ShapeResult m;
  m.header().cloud_id(7);
  m.header().source("two.pcd");
  m.header().object_index(index);
  m.header().object_count(count);
  m.header().timings().preprocess_ms(1.0);
  m.header().timings().solve_ms(2.0);
  pipeline::ObjectResult o;
  o.shape = shape;
  m.objects().push_back(to_msg(o));
  return m;
}

TEST(DdsResultJoiner, JoinsACloudsObjectsInOrder) {
  ResultJoiner joiner;
  EXPECT_FALSE(joiner.add(object_result(1, 2, "sphere")));
  const auto all = joiner.add(object_result(0, 2, "box"));
  ASSERT_TRUE(all);
  EXPECT_EQ(joiner.incomplete(), 0u);
  const pipeline::RecognitionResult r = to_recognition_result(*all);
  ASSERT_EQ(r.objects.size(), 2u);
  EXPECT_EQ(r.objects[0].shape, "box");
  EXPECT_EQ(r.objects[1].shape, "sphere");
  EXPECT_EQ(r.timings.preprocess_ms, 1.0);  // once: ingest timed the whole cloud
  EXPECT_EQ(r.timings.solve_ms, 4.0);       // summed over the objects
  EXPECT_EQ(r.timings.total_ms, 5.0);
}

TEST(DdsResultJoiner, SingleAndEmptyCloudsCompleteAtOnce) {
  ResultJoiner joiner;
  EXPECT_TRUE(joiner.add(object_result(0, 1, "box")));
  msg::ShapeResult empty = object_result(0, 0, "box");
  empty.header().cloud_id(8);
  empty.objects().clear();
  const auto none = joiner.add(empty);
  ASSERT_TRUE(none);
  EXPECT_TRUE(to_recognition_result(*none).objects.empty());
}

// A cloud sent again after a fault comes back twice, possibly half from each attempt: the
// joiner completes it once and drops every later sample of it.
TEST(DdsResultJoiner, DropsDuplicatesOfObjectsAndOfCompletedClouds) {
  ResultJoiner joiner;
  EXPECT_FALSE(joiner.add(object_result(0, 2, "box")));
  EXPECT_FALSE(joiner.add(object_result(0, 2, "box")));
  ASSERT_TRUE(joiner.add(object_result(1, 2, "sphere")));
  EXPECT_FALSE(joiner.add(object_result(0, 2, "box")));
  EXPECT_FALSE(joiner.add(object_result(1, 2, "sphere")));
  msg::ShapeResult single = object_result(0, 1, "cone");
  single.header().cloud_id(9);
  EXPECT_TRUE(joiner.add(single));
  EXPECT_FALSE(joiner.add(single));
  EXPECT_EQ(joiner.duplicates(), 4u);
  EXPECT_EQ(joiner.incomplete(), 0u);
}

TEST(DdsResultJoiner, MemoryIsBoundedOnAnEndlessStream) {
  ResultJoiner joiner(4);
  for (std::uint64_t id = 0; id < 100; ++id) {
    msg::ShapeResult first_of_two = object_result(0, 2, "box");
    first_of_two.header().cloud_id(id);
    EXPECT_FALSE(joiner.add(first_of_two));
  }
  EXPECT_LE(joiner.incomplete(), 4u);
  // Only the last few completions are remembered: an old cloud id completes again.
  for (std::uint64_t id = 1000; id < 1010; ++id) {
    msg::ShapeResult single = object_result(0, 1, "box");
    single.header().cloud_id(id);
    EXPECT_TRUE(joiner.add(single));
  }
  msg::ShapeResult old = object_result(0, 1, "box");
  old.header().cloud_id(1000);
  EXPECT_TRUE(joiner.add(old));
}

}  // namespace
}  // namespace cloudshape::dds
