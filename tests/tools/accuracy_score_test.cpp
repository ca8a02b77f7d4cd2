// The accuracy scorer (tools/bench/accuracy_score) against answers made by hand: right,
// wrong, missed and false objects, known dimension/centre/axis errors, multi-object matching.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <string>

#include "accuracy_score.hpp"

namespace cloudshape::bench {
namespace {

using pipeline::ObjectResult;
using pipeline::RecognitionResult;

constexpr double kExact = 1e-12;
constexpr double kPi = 3.14159265358979323846;

Truth box_truth(const Eigen::Vector3d& center) {
  Truth t;
  t.shape = "box";
  t.dimensions = {{"length", 30.0}, {"width", 20.0}, {"height", 10.0}};
  t.center = center;
  t.size = 30.0;
  t.axis_checks = {{0, false}, {1, false}, {2, false}};
  return t;
}

Truth cone_truth(const Eigen::Vector3d& center) {
  Truth t;
  t.shape = "cone";
  t.dimensions = {{"radius", 10.0}, {"height", 40.0}};
  t.center = center;
  t.size = 40.0;
  t.axis_checks = {{0, true}};
  return t;
}

// The result a perfect recognizer gives for `t`.
ObjectResult answer(const Truth& t) {
  ObjectResult o;
  o.shape = t.shape;
  o.confidence = 0.9;
  o.dimensions = t.dimensions;
  o.center = t.center;
  o.axes = t.axes;
  return o;
}

TestCloud cloud_of(std::initializer_list<Truth> truths, bool gate = false) {
  TestCloud c;
  c.truths = truths;
  c.gate_matching = gate;
  return c;
}

RecognitionResult result_of(std::initializer_list<ObjectResult> objects) {
  RecognitionResult r;
  r.objects = objects;
  return r;
}

TEST(AccuracyScore, RightObjectHasNoError) {
  const TestCloud cloud = cloud_of({box_truth({1, 2, 3})});
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({answer(cloud.truths[0])}), tallies);
  ASSERT_EQ(tallies.size(), 1u);
  const Tally& t = tallies.at("box");
  EXPECT_EQ(t.objects, 1);
  EXPECT_EQ(t.right, 1);
  EXPECT_EQ(t.matched, 1);
  EXPECT_EQ(t.shaped, 1);
  EXPECT_EQ(t.missed, 0);
  EXPECT_EQ(t.false_objects, 0);
  EXPECT_TRUE(t.wrong_as.empty());
  ASSERT_EQ(t.dimension_errors.size(), 3u);
  for (double e : t.dimension_errors) EXPECT_NEAR(e, 0.0, kExact);
  ASSERT_EQ(t.centre_errors.size(), 1u);
  EXPECT_NEAR(t.centre_errors[0], 0.0, kExact);
  ASSERT_EQ(t.axis_errors_deg.size(), 3u);
  for (double e : t.axis_errors_deg) EXPECT_NEAR(e, 0.0, 1e-6);
}

TEST(AccuracyScore, WrongShapeIsCountedAsWhatItWasTakenFor) {
  const TestCloud cloud = cloud_of({cone_truth({0, 0, 0})});
  ObjectResult got = answer(cloud.truths[0]);
  got.shape = "cylinder";
  got.dimensions = {{"radius", 12.0}, {"height", 40.0}};
  got.partial = true;
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({got}), tallies);
  const Tally& t = tallies.at("cone");
  EXPECT_EQ(t.objects, 1);
  EXPECT_EQ(t.right, 0);
  EXPECT_EQ(t.matched, 1);
  EXPECT_EQ(t.partial, 1);
  EXPECT_EQ(t.missed, 0);
  EXPECT_EQ(t.wrong_as, (std::map<std::string, int>{{"cylinder", 1}}));
  // A wrong shape's dimensions, centre and axes are not errors of a right answer.
  EXPECT_TRUE(t.dimension_errors.empty());
  EXPECT_TRUE(t.centre_errors.empty());
  EXPECT_TRUE(t.axis_errors_deg.empty());
  EXPECT_EQ(tallies.count("cylinder"), 0u);
}

TEST(AccuracyScore, NoResultIsAMissedObject) {
  const TestCloud cloud = cloud_of({box_truth({0, 0, 0})});
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({}), tallies);
  const Tally& t = tallies.at("box");
  EXPECT_EQ(t.objects, 1);
  EXPECT_EQ(t.right, 0);
  EXPECT_EQ(t.matched, 0);
  EXPECT_EQ(t.missed, 1);
  EXPECT_EQ(t.wrong_as, (std::map<std::string, int>{{"missed", 1}}));
}

TEST(AccuracyScore, UnknownIsMatchedButNeitherRightNorShaped) {
  const TestCloud cloud = cloud_of({box_truth({0, 0, 0})});
  ObjectResult got;
  got.reason = "all points coplanar";
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({got}), tallies);
  const Tally& t = tallies.at("box");
  EXPECT_EQ(t.matched, 1);
  EXPECT_EQ(t.shaped, 0);
  EXPECT_EQ(t.right, 0);
  EXPECT_EQ(t.missed, 0);
  EXPECT_EQ(t.wrong_as, (std::map<std::string, int>{{"unknown", 1}}));
}

// The nearer result answers; the other is a false object of the nearest truth's shape.
TEST(AccuracyScore, ExtraResultIsAFalseObjectOfTheNearestTruth) {
  const TestCloud cloud = cloud_of({box_truth({0, 0, 0})});
  ObjectResult ghost = answer(cloud.truths[0]);
  ghost.shape = "sphere";
  ghost.center = {25, 0, 0};
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({ghost, answer(cloud.truths[0])}), tallies);
  const Tally& t = tallies.at("box");
  EXPECT_EQ(t.right, 1);
  EXPECT_EQ(t.false_objects, 1);
  EXPECT_EQ(t.missed, 0);
  EXPECT_TRUE(t.wrong_as.empty());
}

TEST(AccuracyScore, DimensionOffByAKnownAmountGivesThatRelativeError) {
  const TestCloud cloud = cloud_of({box_truth({0, 0, 0})});
  ObjectResult got = answer(cloud.truths[0]);
  got.dimensions = {{"length", 33.0}, {"width", 19.0}, {"height", 10.0}};
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({got}), tallies);
  const Tally& t = tallies.at("box");
  EXPECT_EQ(t.right, 1);
  ASSERT_EQ(t.dimension_errors.size(), 3u);
  EXPECT_NEAR(t.dimension_errors[0], 0.10, kExact);  // 3 of 30
  EXPECT_NEAR(t.dimension_errors[1], 0.05, kExact);  // 1 of 20
  EXPECT_NEAR(t.dimension_errors[2], 0.00, kExact);
}

// Dimensions are compared by name, whatever order the result lists them in; a name the
// truth lacks is not scored.
TEST(AccuracyScore, DimensionsAreMatchedByName) {
  const Truth truth = cone_truth({0, 0, 0});
  ObjectResult got = answer(truth);
  got.dimensions = {{"height", 36.0}, {"apex_angle", 1.0}, {"radius", 11.0}};
  const std::vector<double> e = dimension_errors(truth, got);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_NEAR(e[0], 0.1, kExact);  // radius: 1 of 10, the truth's order
  EXPECT_NEAR(e[1], 0.1, kExact);  // height: 4 of 40
}

TEST(AccuracyScore, CentreErrorIsRelativeToSize) {
  const TestCloud cloud = cloud_of({box_truth({0, 0, 0})});
  ObjectResult got = answer(cloud.truths[0]);
  got.center = {3, 4, 0};  // 5 away, size 30
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({got}), tallies);
  ASSERT_EQ(tallies.at("box").centre_errors.size(), 1u);
  EXPECT_NEAR(tallies.at("box").centre_errors[0], 5.0 / 30.0, kExact);
}

TEST(AccuracyScore, AxisErrorIsTheAngleSignFreeExceptWhereTheSignMeansSomething) {
  // The result's frame turned 10 degrees about z: axes 0 and 1 are 10 degrees off, axis 2 not.
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(10.0 * kPi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const TestCloud boxes = cloud_of({box_truth({0, 0, 0})});
  ObjectResult box = answer(boxes.truths[0]);
  box.axes = turned.transpose();  // rows are the turned axes
  box.axes.row(1) *= -1.0;        // a box's axis has no sign
  std::map<std::string, Tally> tallies;
  score_cloud(boxes, result_of({box}), tallies);
  const auto& box_errors = tallies.at("box").axis_errors_deg;
  ASSERT_EQ(box_errors.size(), 3u);
  EXPECT_NEAR(box_errors[0], 10.0, 1e-6);
  EXPECT_NEAR(box_errors[1], 10.0, 1e-6);
  EXPECT_NEAR(box_errors[2], 0.0, 1e-6);

  const TestCloud cones = cloud_of({cone_truth({0, 0, 0})});
  ObjectResult upside_down = answer(cones.truths[0]);
  upside_down.axes.row(0) *= -1.0;  // apex where the base is
  score_cloud(cones, result_of({upside_down}), tallies);
  ASSERT_EQ(tallies.at("cone").axis_errors_deg.size(), 1u);
  EXPECT_NEAR(tallies.at("cone").axis_errors_deg[0], 180.0, 1e-6);
}

TEST(AccuracyScore, NoPoseTruthScoresShapeAndDimensionsOnly) {
  Truth truth = box_truth({0, 0, 0});
  truth.has_pose = false;
  const TestCloud cloud = cloud_of({truth});
  ObjectResult got = answer(truth);
  got.center = {10, 0, 0};
  got.dimensions[0].second = 27.0;
  std::map<std::string, Tally> tallies;
  score_cloud(cloud, result_of({got}), tallies);
  const Tally& t = tallies.at("box");
  EXPECT_EQ(t.right, 1);
  ASSERT_EQ(t.dimension_errors.size(), 3u);
  EXPECT_NEAR(t.dimension_errors[0], 0.1, kExact);
  EXPECT_TRUE(t.centre_errors.empty());
  EXPECT_TRUE(t.axis_errors_deg.empty());
}

// An unknown result has no pose (centre at the origin), so a result with a shape answers
// first even when the unknown one happens to sit nearer.
TEST(AccuracyScore, AShapedResultAnswersBeforeAnUnknownOne) {
  const TestCloud cloud = cloud_of({box_truth({0, 0, 0})});
  ObjectResult unknown;
  ObjectResult box = answer(cloud.truths[0]);
  box.center = {6, 0, 0};
  EXPECT_EQ(match_results(cloud, result_of({unknown, box})), (std::vector<int>{1}));
}

// Three solids far apart, results listed in another order: each truth gets the result at
// its centre. A result more than half a size from every truth answers none (false), and the
// truth it was meant for is missed.
TEST(AccuracyScore, MultiObjectMatchingByCentreWithinHalfASize) {
  const TestCloud cloud =
      cloud_of({box_truth({0, 0, 0}), cone_truth({100, 0, 0}), box_truth({0, 100, 0})}, true);
  ObjectResult far_box = answer(cloud.truths[2]);
  far_box.center = {0, 116, 0};  // 16 from its truth: beyond 0.5 x 30
  const RecognitionResult r =
      result_of({far_box, answer(cloud.truths[1]), answer(cloud.truths[0])});
  EXPECT_EQ(match_results(cloud, r), (std::vector<int>{2, 1, -1}));

  std::map<std::string, Tally> tallies;
  score_cloud(cloud, r, tallies);
  EXPECT_EQ(tallies.at("box").objects, 2);
  EXPECT_EQ(tallies.at("box").right, 1);
  EXPECT_EQ(tallies.at("box").missed, 1);
  EXPECT_EQ(tallies.at("box").false_objects, 1);
  EXPECT_EQ(tallies.at("cone").objects, 1);
  EXPECT_EQ(tallies.at("cone").right, 1);
  EXPECT_EQ(tallies.at("cone").false_objects, 0);

  // Without the gate (one truth per cloud) the nearest result answers wherever it lies.
  TestCloud one = cloud_of({box_truth({0, 0, 0})});
  ObjectResult off = answer(one.truths[0]);
  off.center = {0, 50, 0};
  EXPECT_EQ(match_results(one, result_of({off})), (std::vector<int>{0}));
}

// Two truths near one result: the nearer truth takes it, greedily by distance.
TEST(AccuracyScore, EachResultAnswersOneTruthTheNearest) {
  const TestCloud cloud = cloud_of({box_truth({0, 0, 0}), box_truth({12, 0, 0})}, true);
  ObjectResult between = answer(cloud.truths[0]);
  between.center = {8, 0, 0};
  EXPECT_EQ(match_results(cloud, result_of({between})), (std::vector<int>{-1, 0}));
}

TEST(AccuracyScore, MergeAddsEveryShapesTally) {
  std::map<std::string, Tally> tallies;
  const TestCloud boxes = cloud_of({box_truth({0, 0, 0})});
  const TestCloud cones = cloud_of({cone_truth({0, 0, 0})});
  ObjectResult wrong = answer(cones.truths[0]);
  wrong.shape = "cylinder";
  score_cloud(boxes, result_of({answer(boxes.truths[0])}), tallies);
  score_cloud(cones, result_of({wrong}), tallies);
  score_cloud(cones, result_of({}), tallies);
  const Tally all = merge(tallies);
  EXPECT_EQ(all.objects, 3);
  EXPECT_EQ(all.right, 1);
  EXPECT_EQ(all.matched, 2);
  EXPECT_EQ(all.missed, 1);
  EXPECT_EQ(all.dimension_errors.size(), 3u);
  EXPECT_EQ(all.wrong_as, (std::map<std::string, int>{{"cylinder", 1}, {"missed", 1}}));
}

}  // namespace
}  // namespace cloudshape::bench
