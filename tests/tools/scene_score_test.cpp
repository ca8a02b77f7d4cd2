// The scene scorer against hand-made answers on a hand-made labelled scene: right, wrong shape,
// missed, false, duplicate, table, an object found by one of two parts, a known IoU, centre rule.
#include <gtest/gtest.h>

#include <stdexcept>

#include "scene_score.hpp"

namespace cloudshape::bench {
namespace {

// A 1 m table (label 1, 40 x 40 points at z = 0) with, on it, three objects of 10 cm cubes'
// worth of points: 20 (200 points), 30 (200 points), 40 + 41 (one occluded object in two
// parts of 100 points each), and a 20-point fragment labelled 50 (under the 50-point floor).
struct Scene {
  PointList points;
  std::vector<std::uint32_t> labels;
  std::map<std::uint32_t, std::vector<std::uint32_t>> of;  // label -> its point indices

  void add(std::uint32_t label, const Eigen::Vector3d& centre, int nx, int ny, int nz,
           double side) {
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        for (int k = 0; k < nz; ++k) {
          const Eigen::Vector3d unit((i + 0.5) / nx - 0.5, (j + 0.5) / ny - 0.5,
                                     nz > 1 ? (k + 0.5) / nz - 0.5 : 0.0);
          of[label].push_back(static_cast<std::uint32_t>(points.size()));
          points.push_back(centre + side * unit);
          labels.push_back(label);
        }
      }
    }
  }

  // The first `n` points of `label` (all when n is 0).
  std::vector<std::uint32_t> take(std::uint32_t label, std::size_t n = 0) const {
    const auto& all = of.at(label);
    return {all.begin(), all.begin() + static_cast<std::ptrdiff_t>(n == 0 ? all.size() : n)};
  }

  Eigen::Vector3d centroid(std::uint32_t label) const {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto i : of.at(label)) c += points[i];
    return c / static_cast<double>(of.at(label).size());
  }
};

Scene make_scene() {
  Scene s;
  s.add(1, {0.0, 0.0, 0.0}, 40, 40, 1, 1.0);
  s.add(20, {0.25, 0.25, 0.05}, 5, 5, 8, 0.1);
  s.add(30, {-0.25, 0.25, 0.05}, 5, 5, 8, 0.1);
  s.add(40, {0.0, -0.2, 0.05}, 5, 5, 4, 0.1);
  s.add(41, {0.0, -0.35, 0.05}, 5, 5, 4, 0.1);
  s.add(50, {0.3, -0.3, 0.05}, 2, 2, 5, 0.02);
  return s;
}

SceneTruth truth_boxes_and_a_can() {
  SceneTruth t;
  t.category = "test";
  t.default_shapes = {"box"};
  t.object_shapes[4] = {"cylinder"};
  return t;
}

ReportedObject by_points(const std::string& shape, std::vector<std::uint32_t> indices) {
  ReportedObject r;
  r.shape = shape;
  r.point_indices = std::move(indices);
  return r;
}

ReportedObject by_centre(const std::string& shape, const Eigen::Vector3d& c, double diameter) {
  ReportedObject r;
  r.shape = shape;
  r.center = c;
  r.diameter = diameter;
  return r;
}

std::vector<std::uint32_t> join(std::vector<std::uint32_t> a, const std::vector<std::uint32_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

const ObjectScore& object(const SceneScore& s, std::uint32_t number) {
  for (const auto& o : s.objects) {
    if (o.object == number) return o;
  }
  throw std::out_of_range("no object " + std::to_string(number));
}

TEST(SceneScore, ObjectsAreTheLabelledObjectsWithTheirPartsAndNoFragments) {
  const Scene s = make_scene();
  const SceneScore score = score_scene(s.points, s.labels, truth_boxes_and_a_can(), {});
  ASSERT_EQ(score.objects.size(), 3u);  // 2, 3, 4; 50 has 20 points
  EXPECT_EQ(object(score, 4).parts, (std::vector<std::uint32_t>{40, 41}));
  EXPECT_EQ(object(score, 4).points, 200u);
  EXPECT_EQ(score.missed, 3);
  EXPECT_EQ(score.right + score.wrong_shape + score.false_objects + score.duplicates, 0);
}

TEST(SceneScore, RightWrongShapeAndMissed) {
  const Scene s = make_scene();
  const SceneScore score =
      score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                  {by_points("box", s.take(20)), by_points("cylinder", s.take(30))});
  EXPECT_EQ(object(score, 2).outcome, ObjectOutcome::right);
  EXPECT_EQ(object(score, 3).outcome, ObjectOutcome::wrong_shape);
  EXPECT_EQ(object(score, 3).reported_shapes, (std::vector<std::string>{"cylinder"}));
  EXPECT_EQ(object(score, 4).outcome, ObjectOutcome::missed);
  EXPECT_EQ(score.right, 1);
  EXPECT_EQ(score.wrong_shape, 1);
  EXPECT_EQ(score.missed, 1);
  EXPECT_EQ(score.false_objects, 0);
}

TEST(SceneScore, AReportWithoutAMajorityLabelIsFalseAndTheTableIsNot) {
  const Scene s = make_scene();
  // Exactly half on 20 and half on 30: no label holds more than half.
  const SceneScore score = score_scene(
      s.points, s.labels, truth_boxes_and_a_can(),
      {by_points("box", join(s.take(20, 60), s.take(30, 60))), by_points("box", s.take(1, 900))});
  ASSERT_EQ(score.reports.size(), 2u);
  EXPECT_EQ(score.reports[0].kind, ReportKind::false_object);
  EXPECT_EQ(score.reports[1].kind, ReportKind::table);
  EXPECT_EQ(score.false_objects, 1);
  EXPECT_EQ(score.table, 1);
  EXPECT_EQ(score.missed, 3);
}

TEST(SceneScore, ASecondReportOnOneGroupIsADuplicateAndTheLargerOverlapWins) {
  const Scene s = make_scene();
  std::vector<std::uint32_t> rest(s.of.at(20).begin() + 150, s.of.at(20).end());
  const SceneScore score =
      score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                  {by_points("cone", rest), by_points("box", s.take(20, 150))});
  EXPECT_EQ(score.reports[0].kind, ReportKind::duplicate);
  EXPECT_EQ(score.reports[1].kind, ReportKind::match);
  EXPECT_EQ(score.duplicates, 1);
  EXPECT_EQ(score.false_objects, 0);
  EXPECT_EQ(object(score, 2).outcome, ObjectOutcome::right);
  EXPECT_EQ(object(score, 2).reported_shapes, (std::vector<std::string>{"box"}));
}

TEST(SceneScore, ATwoPartObjectIsFoundByOnePartAndItsOtherPartIsNoDuplicate) {
  const Scene s = make_scene();
  const SceneScore one =
      score_scene(s.points, s.labels, truth_boxes_and_a_can(), {by_points("cylinder", s.take(41))});
  EXPECT_EQ(object(one, 4).outcome, ObjectOutcome::right);
  EXPECT_EQ(one.right, 1);

  const SceneScore both =
      score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                  {by_points("cylinder", s.take(41)), by_points("box", s.take(40))});
  EXPECT_EQ(object(both, 4).outcome, ObjectOutcome::right);  // one part has the accepted shape
  EXPECT_EQ(both.duplicates, 0);
  EXPECT_EQ(both.false_objects, 0);
  EXPECT_EQ(both.right, 1);
  // Each part found alone: IoU of the whole object is 100 / 200 points.
  EXPECT_NEAR(object(one, 4).iou, 0.5, 1e-12);
  EXPECT_NEAR(object(both, 4).iou, 1.0, 1e-12);
}

TEST(SceneScore, AReportJoiningBothPartsOfAnObjectIsThatObject) {
  const Scene s = make_scene();
  // 100 points on each part and 60 on 20: neither part holds half, the object does (200/260).
  const SceneScore score =
      score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                  {by_points("cylinder", join(join(s.take(40), s.take(41)), s.take(20, 60)))});
  EXPECT_EQ(score.reports[0].kind, ReportKind::match);
  EXPECT_EQ(object(score, 4).outcome, ObjectOutcome::right);
  EXPECT_EQ(object(score, 2).outcome, ObjectOutcome::missed);
  EXPECT_EQ(score.false_objects, 0);
  EXPECT_NEAR(object(score, 4).iou, 200.0 / 260.0, 1e-12);
}

TEST(SceneScore, IouOfAKnownOverlap) {
  const Scene s = make_scene();
  // 150 of the 200 points of 20 plus 50 table points: 150 / (200 + 200 - 150).
  const SceneScore score = score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                                       {by_points("box", join(s.take(20, 150), s.take(1, 50)))});
  EXPECT_EQ(score.reports[0].kind, ReportKind::match);
  EXPECT_NEAR(score.reports[0].share, 0.75, 1e-12);
  EXPECT_NEAR(object(score, 2).iou, 0.6, 1e-12);
  EXPECT_LT(object(score, 3).iou, 0.0);  // missed: not measured
}

TEST(SceneScore, RepeatedIndicesCountOnce) {
  const Scene s = make_scene();
  const SceneScore score = score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                                       {by_points("box", join(s.take(20), s.take(20)))});
  EXPECT_NEAR(object(score, 2).iou, 1.0, 1e-12);
}

TEST(SceneScore, AFragmentUnderTheFloorIsNeitherAnObjectNorFalse) {
  const Scene s = make_scene();
  const SceneScore score =
      score_scene(s.points, s.labels, truth_boxes_and_a_can(), {by_points("sphere", s.take(50))});
  EXPECT_EQ(score.reports[0].kind, ReportKind::ignored_group);
  EXPECT_EQ(score.false_objects, 0);
  EXPECT_EQ(score.objects.size(), 3u);
}

TEST(SceneScore, CentreRuleMatchesTheNearestGroupOfAFittingSize) {
  const Scene s = make_scene();
  const double cube_diagonal = 0.1 * std::sqrt(3.0);
  const SceneScore score = score_scene(
      s.points, s.labels, truth_boxes_and_a_can(),
      {by_centre("box", s.centroid(20), cube_diagonal),
       // Beside 30, 3 cm from its nearest point: still 30 (half its size is about 8.5 cm).
       by_centre("box", s.centroid(30) + Eigen::Vector3d(0.07, 0.0, 0.0), cube_diagonal),
       // Between 40 and 41, nearer 41: a report on the same object's other part.
       by_centre("cylinder", {0.0, -0.29, 0.05}, 0.12)});
  EXPECT_EQ(score.reports[0].kind, ReportKind::match);
  EXPECT_EQ(score.reports[0].label, 20u);
  EXPECT_TRUE(score.reports[0].by_centre);
  EXPECT_EQ(score.reports[1].label, 30u);
  EXPECT_EQ(score.reports[2].label, 41u);
  EXPECT_EQ(score.right, 3);
  EXPECT_LT(object(score, 2).iou, 0.0);  // no indices: IoU not measurable
}

TEST(SceneScore, CentreRuleRejectsAnOversizedSolidAndFarCentres) {
  const Scene s = make_scene();
  const SceneScore score = score_scene(
      s.points, s.labels, truth_boxes_and_a_can(),
      {// On 20, but 1.2 m across: object and table merged, reported as the table.
       by_centre("box", s.centroid(20), 1.2),
       // 0.5 m above the table: nothing.
       by_centre("box", {0.0, 0.0, 0.5}, 0.1),
       // On the table, 5 cm across: too small to be the table, near no object: false.
       by_centre("box", {-0.3, -0.3, 0.02}, 0.05),
       // 40 cm across, 10 cm over the table: too large for any object, under half the table.
       by_centre("cylinder", {-0.3, -0.3, 0.1}, 0.4)});
  EXPECT_EQ(score.reports[0].kind, ReportKind::table);
  EXPECT_EQ(score.reports[1].kind, ReportKind::false_object);
  EXPECT_EQ(score.reports[2].kind, ReportKind::false_object);
  EXPECT_EQ(score.reports[3].kind, ReportKind::false_object);
  EXPECT_EQ(score.false_objects, 3);
  EXPECT_EQ(score.missed, 3);
}

TEST(SceneScore, AReportWithIndicesOutranksOneByCentre) {
  const Scene s = make_scene();
  const SceneScore score =
      score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                  {by_centre("cone", s.centroid(20), 0.17), by_points("box", s.take(20, 60))});
  EXPECT_EQ(score.reports[0].kind, ReportKind::duplicate);
  EXPECT_EQ(score.reports[1].kind, ReportKind::match);
  EXPECT_EQ(object(score, 2).outcome, ObjectOutcome::right);
}

TEST(SceneScore, BadInputIsNamed) {
  const Scene s = make_scene();
  std::vector<std::uint32_t> short_labels(s.labels.begin(), s.labels.end() - 1);
  EXPECT_THROW(score_scene(s.points, short_labels, truth_boxes_and_a_can(), {}),
               std::invalid_argument);
  EXPECT_THROW(score_scene(s.points, s.labels, truth_boxes_and_a_can(),
                           {by_points("box", {static_cast<std::uint32_t>(s.points.size())})}),
               std::invalid_argument);
  SceneTruth none;
  none.object_shapes[2] = {"box"};
  try {
    score_scene(s.points, s.labels, none, {});
    FAIL() << "objects 3 and 4 have no shape in the truth";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("label 30"), std::string::npos) << e.what();
  }
}

TEST(SceneScore, DiameterFollowsTheShapesDimensions) {
  pipeline::ObjectResult box;
  box.shape = "box";
  box.dimensions = {{"length", 0.3}, {"width", 0.2}, {"height", 0.1}};
  EXPECT_NEAR(reported_object(box).diameter, std::sqrt(0.14), 1e-12);
  pipeline::ObjectResult can;
  can.shape = "cylinder";
  can.dimensions = {{"radius", 0.04}, {"height", 0.06}};
  EXPECT_NEAR(reported_object(can).diameter, 0.1, 1e-12);
  pipeline::ObjectResult unknown;
  EXPECT_EQ(reported_object(unknown).diameter, 0.0);
}

}  // namespace
}  // namespace cloudshape::bench
