// Several separate objects in one cloud give one result each (INTERFACE.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "config/pipeline_config.hpp"
#include "pipeline/recognize.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape {
namespace {

synth::Pose at(double x, double y, double z, double angle) {
  synth::Pose p;
  p.center = Eigen::Vector3d(x, y, z);
  p.axes = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  return p;
}

TEST(MultiObject, ThreeSeparateSolidsGiveThreeResults) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, at(0, 0, 0, 0.3)),
      synth::make_solid(synth::ShapeKind::cylinder, {0.8, 2.0}, at(6, 0, 0, 1.1)),
      synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(0, 6, 1, 0.0)),
  };
  synth::CloudOptions opts;
  opts.points = 60000;
  const auto cloud = synth::make_synthetic_cloud(solids, opts, 5);
  const auto result = pipeline::recognize_cloud(cloud.points, config::PipelineConfig{}, "three");
  ASSERT_EQ(result.objects.size(), 3u);
  for (const auto& truth : solids) {
    // The result whose centre is nearest this solid's centre must be this solid.
    const auto nearest = std::min_element(result.objects.begin(), result.objects.end(),
                                          [&](const auto& a, const auto& b) {
                                            return (a.center - truth.pose.center).norm() <
                                                   (b.center - truth.pose.center).norm();
                                          });
    EXPECT_EQ(nearest->shape, synth::to_string(truth.kind));
    EXPECT_LT((nearest->center - truth.pose.center).norm(), 0.05);
    for (std::size_t d = 0; d < truth.dimensions.size(); ++d)
      EXPECT_NEAR(nearest->dimensions[d].second, truth.dimensions[d].second,
                  0.01 * truth.dimensions[d].second);
  }
}

TEST(MultiObject, TwoSpheresApartGiveTwoResults) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(0, 0, 0, 0)),
      synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(5, 0, 0, 0)),
  };
  synth::CloudOptions opts;
  opts.points = 20000;
  const auto cloud = synth::make_synthetic_cloud(solids, opts, 6);
  config::PipelineConfig cfg;
  const auto result = pipeline::recognize_cloud(cloud.points, cfg, "two");
  ASSERT_EQ(result.objects.size(), 2u);
  for (const auto& o : result.objects) EXPECT_EQ(o.shape, "sphere");
}

// A sensor leaves narrow strips along silhouettes (mixed pixels, edge shadows); one detached
// from its object must not come out as a second object, but a small solid must.
TEST(MultiObject, ANarrowStripIsAFragmentButASmallSolidIsAnObject) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, at(0, 0, 0, 0.3))};
  synth::CloudOptions opts;
  opts.points = 30000;
  PointList points = synth::make_synthetic_cloud(solids, opts, 8).points;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointList with_strip = points;
  for (int i = 0; i < 3000; ++i)  // 3 long, 0.12 wide, flat: 10% of the box's points
    with_strip.emplace_back(-1.5 + 3.0 * u(rng), 3.0 + 0.12 * u(rng), 0.0);
  const auto stripped = pipeline::recognize_cloud(with_strip, config::PipelineConfig{}, "strip");
  ASSERT_EQ(stripped.objects.size(), 1u);
  EXPECT_EQ(stripped.objects.front().shape, "box");

  const auto small = synth::make_synthetic_cloud(
      {synth::make_solid(synth::ShapeKind::sphere, {0.25}, at(0, 4, 0, 0))}, [] {
        synth::CloudOptions o;
        o.points = 1500;
        return o;
      }(), 10);
  PointList with_small = points;
  with_small.insert(with_small.end(), small.points.begin(), small.points.end());
  const auto both = pipeline::recognize_cloud(with_small, config::PipelineConfig{}, "small");
  ASSERT_EQ(both.objects.size(), 2u);
  EXPECT_EQ(both.objects[1].shape, "sphere");
}

// Objects standing on a table much larger than they are: the table goes, the objects stay.
TEST(MultiObject, ATableUnderTheObjectsIsRemoved) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, at(0, 0, 0.5, 0.0)),
      synth::make_solid(synth::ShapeKind::cylinder, {0.8, 2.0}, [] {
        synth::Pose p;  // axis (local x) up: standing on a cap
        p.center = Eigen::Vector3d(4, 1, 1.0);
        p.axes = Eigen::AngleAxisd(-1.5707963267948966, Eigen::Vector3d::UnitY()).toRotationMatrix().transpose();
        return p;
      }())};
  synth::CloudOptions opts;
  opts.points = 20000;
  opts.view = Eigen::Vector3d(2, -12, 10);
  PointList points = synth::make_synthetic_cloud(solids, opts, 12).points;
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-6.0, 8.0);
  for (int i = 0; i < 30000; ++i) {  // the table top, hidden under the objects
    const Point p(u(rng), u(rng) - 1.0, 0.0);
    const bool under_box = std::abs(p.x()) < 1.5 && std::abs(p.y()) < 1.0;
    const bool under_cylinder = (p - Point(4, 1, 0)).norm() < 0.8;
    if (!under_box && !under_cylinder) points.push_back(p);
  }
  const auto cfg = config::PipelineConfig{};
  const auto result = pipeline::recognize_cloud(points, cfg, "table");
  ASSERT_EQ(result.objects.size(), 2u);
  std::vector<std::string> shapes{result.objects[0].shape, result.objects[1].shape};
  std::sort(shapes.begin(), shapes.end());
  EXPECT_EQ(shapes, (std::vector<std::string>{"box", "cylinder"}));
}

TEST(SingleView, ABoxSeenFromOneSideIsPartial) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, at(0, 0, 0, 0.3))};
  synth::CloudOptions opts;
  opts.points = 20000;
  opts.view = Eigen::Vector3d(6, 5, 4);
  const auto cloud = synth::make_synthetic_cloud(solids, opts, 7);
  const auto result = pipeline::recognize_cloud(cloud.points, config::PipelineConfig{}, "view");
  ASSERT_EQ(result.objects.size(), 1u);
  const auto& got = result.objects.front();
  EXPECT_TRUE(got.partial);
  EXPECT_LT(got.confidence, 0.9);
  // The camera lies beyond all three faces that meet at the nearest corner (its local
  // coordinates exceed the half-edges), so every edge is seen whole: the view determines all
  // three dimensions and the centre. Tolerance as the single-view box test's (box_parameters_test).
  const Eigen::Vector3d local = solids[0].pose.axes * (*opts.view - solids[0].pose.center);
  for (int k = 0; k < 3; ++k) ASSERT_GT(std::abs(local[k]), 0.5 * solids[0].dimensions[k].second);
  ASSERT_EQ(got.shape, "box");
  for (std::size_t d = 0; d < 3; ++d)
    EXPECT_NEAR(got.dimensions[d].second, solids[0].dimensions[d].second,
                0.01 * solids[0].dimensions[d].second)
        << solids[0].dimensions[d].first;
  EXPECT_LT((got.center - solids[0].pose.center).norm(), 0.01 * 3.0);
}

}  // namespace
}  // namespace cloudshape
