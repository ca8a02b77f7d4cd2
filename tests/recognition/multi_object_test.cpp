// Several separate objects in one cloud give one result each (INTERFACE.md).
#include <gtest/gtest.h>

#include <algorithm>

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

TEST(MultiObject, SplittingOffGivesOneResult) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(0, 0, 0, 0)),
      synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(5, 0, 0, 0)),
  };
  synth::CloudOptions opts;
  opts.points = 20000;
  const auto cloud = synth::make_synthetic_cloud(solids, opts, 6);
  config::PipelineConfig cfg;
  EXPECT_EQ(pipeline::recognize_cloud(cloud.points, cfg, "two").objects.size(), 2u);
  cfg.preprocess.split_objects = false;
  EXPECT_EQ(pipeline::recognize_cloud(cloud.points, cfg, "two").objects.size(), 1u);
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
}

}  // namespace
}  // namespace cloudshape
