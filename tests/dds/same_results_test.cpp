// The DDS "same result" comparison against hand-made pairs: what it must accept (the contract's
// freedom: axis signs, a sphere's axes, a box's equal pair) and what it must refuse.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "same_axes.hpp"
#include "same_results.hpp"

namespace cloudshape::testing {
namespace {

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

pipeline::ObjectResult object(const std::string& shape, std::vector<std::pair<std::string, double>> dims) {
  pipeline::ObjectResult o;
  o.shape = shape;
  o.dimensions = std::move(dims);
  o.confidence = 0.9;
  o.center = {1.0, 2.0, 3.0};
  o.axes = rotation(0.7, {1, 2, 3});  // rows: a general orientation
  return o;
}

pipeline::ObjectResult box(double l, double w, double h) {
  return object("box", {{"length", l}, {"width", w}, {"height", h}});
}

bool same_axes(const pipeline::ObjectResult& a, const pipeline::ObjectResult& e) {
  return axes_difference(a, e, kSameTolerance).empty();
}

TEST(SameAxes, EachAxisUpToItsSign) {
  const pipeline::ObjectResult e = box(30, 20, 10);
  pipeline::ObjectResult a = e;
  a.axes.row(0) *= -1;
  a.axes.row(2) *= -1;
  EXPECT_TRUE(same_axes(a, e));
  a = e;
  a.axes.row(1).swap(a.axes.row(2));  // distinct edges: the axes are pinned down
  EXPECT_FALSE(same_axes(a, e));
  a = e;
  a.axes = Eigen::Matrix3d::Identity();  // a conversion that dropped the axes
  EXPECT_FALSE(same_axes(a, e));
  a = e;
  a.axes = e.axes * rotation(1e-6, {0, 0, 1});  // off by far more than float64 noise
  EXPECT_FALSE(same_axes(a, e));
  a = e;
  a.axes = e.axes * rotation(1e-12, {0, 0, 1});
  EXPECT_TRUE(same_axes(a, e));
}

TEST(SameAxes, TheConesAxisZeroKeepsItsSign) {
  for (const char* shape : {"cone", "frustum"}) {
    const pipeline::ObjectResult e = object(shape, {{"radius", 5}, {"height", 12}});
    pipeline::ObjectResult a = e;
    a.axes.row(1) *= -1;
    a.axes.row(2) *= -1;
    EXPECT_TRUE(same_axes(a, e)) << shape;
    a.axes.row(0) *= -1;
    a.axes.row(1) *= -1;
    EXPECT_FALSE(same_axes(a, e)) << shape;
  }
  const pipeline::ObjectResult cylinder = object("cylinder", {{"radius", 5}, {"height", 12}});
  pipeline::ObjectResult flipped = cylinder;
  flipped.axes.row(0) *= -1;
  EXPECT_TRUE(same_axes(flipped, cylinder));
}

TEST(SameAxes, ASphereTakesAnyOrthonormalAxesButNoOthers) {
  const pipeline::ObjectResult e = object("sphere", {{"radius", 5}});
  pipeline::ObjectResult a = e;
  a.axes = rotation(2.0, {3, -1, 2});
  EXPECT_TRUE(same_axes(a, e));
  a.axes(0, 0) += 0.01;
  EXPECT_FALSE(same_axes(a, e));
}

TEST(SameAxes, ABoxWithTwoEqualEdgesFixesOnlyTheThirdAxis) {
  // length == width: any orthonormal pair in their plane; the height axis stays.
  pipeline::ObjectResult e = box(20, 20, 10);
  pipeline::ObjectResult a = e;
  const Eigen::Vector3d height = e.axes.row(2).transpose();
  a.axes.topRows<2>() = (rotation(0.4, height) * e.axes.topRows<2>().transpose()).transpose();
  EXPECT_TRUE(same_axes(a, e));
  a.axes.row(2) = e.axes.row(0);  // the plane turned: refused
  a.axes.row(0) = e.axes.row(2);
  EXPECT_FALSE(same_axes(a, e));
  // width == height: the length axis stays.
  e = box(30, 10, 10);
  a = e;
  const Eigen::Vector3d length = e.axes.row(0).transpose();
  a.axes.bottomRows<2>() = (rotation(1.1, length) * e.axes.bottomRows<2>().transpose()).transpose();
  EXPECT_TRUE(same_axes(a, e));
  // Nearly equal is not equal: the solver's choice within the pair is then the result.
  e = box(20.001, 20, 10);
  a = e;
  a.axes.topRows<2>() = (rotation(0.4, e.axes.row(2).transpose()) * e.axes.topRows<2>().transpose()).transpose();
  EXPECT_FALSE(same_axes(a, e));
  // A cube: any orthonormal set.
  e = box(10, 10, 10);
  a = e;
  a.axes = rotation(0.3, {1, 0, 0});
  EXPECT_TRUE(same_axes(a, e));
}

pipeline::RecognitionResult result(const pipeline::ObjectResult& o) {
  pipeline::RecognitionResult r;
  r.source = "x.pcd";
  r.points_in = 100;
  r.points_used = 90;
  r.resolution = 0.5;
  r.objects = {o};
  return r;
}

TEST(SameResults, EveryFieldCounts) {
  const pipeline::RecognitionResult e = result(box(30, 20, 10));
  EXPECT_TRUE(result_differences(e, e, "x").empty());
  const auto differs = [&](auto change) {
    pipeline::RecognitionResult a = e;
    change(a);
    return result_differences(e, a, "x").size() == 1;
  };
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].shape = "cylinder"; }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].dimensions[1].second *= 1 + 1e-8; }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].center.y() += 1e-8 * 2; }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].axes.row(1).swap(a.objects[0].axes.row(2)); }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].confidence += 1e-8; }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].partial = true; }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].reason = "why"; }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].keypoints.corner = 3; }));
  EXPECT_TRUE(differs([](auto& a) { a.points_used = 91; }));
  EXPECT_TRUE(differs([](auto& a) { a.resolution = 0.5 + 1e-8; }));
  EXPECT_TRUE(differs([](auto& a) { a.objects[0].dimensions[0].second *= 1 + 1e-12; }) == false);
  EXPECT_TRUE(differs([](auto& a) { a.timings.total_ms = 99; }) == false);  // a measurement
}

TEST(SameResults, LinesMatchBySourceAndReportStrayOnes) {
  const std::string line =
      R"({"source":"a.pcd","points_in":3,"points_used":3,"resolution":1,"objects":[)"
      R"({"shape":"sphere","confidence":1,"dimensions":{"radius":2},"pose":{"center":[0,0,0],)"
      R"("axes":[[1,0,0],[0,1,0],[0,0,1]]},"partial":false,"keypoints":{"corner":0,"edge":0,"border":0}}],)"
      R"("timings_ms":{"preprocess":0,"planes":0,"keypoints":0,"classify":0,"solve":0,"total":0}})";
  EXPECT_TRUE(result_differences({line}, {line}).empty());
  EXPECT_EQ(result_differences({line}, {}).size(), 1u);         // no result
  EXPECT_EQ(result_differences({}, {line}).size(), 1u);         // unexpected
  EXPECT_EQ(result_differences({line}, {line, line}).size(), 1u);  // twice
  EXPECT_EQ(result_differences({line}, {line, "nonsense"}).size(), 1u);
}

}  // namespace
}  // namespace cloudshape::testing
