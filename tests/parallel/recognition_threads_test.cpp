// recognize_cloud gives byte-identical JSON (timings aside) with 1, 2 and 3 threads: single
// noisy solids, a scene of several objects, and real Kinect frames when ../shared is there.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "pipeline/recognize.hpp"
#include "report/result_json.hpp"
#include "shared_data.hpp"
#include "synth/synthetic_cloud.hpp"

namespace cloudshape {
namespace {

synth::Pose at(double x, double y, double z, double angle) {
  synth::Pose p;
  p.center = Eigen::Vector3d(x, y, z);
  p.axes = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 0).normalized()).toRotationMatrix();
  return p;
}

// The JSON line without its timings, the only part allowed to differ.
std::string answer(const PointList& points, const GridLayout& grid, std::size_t threads) {
  parallel::ThreadPool pool(threads);
  nlohmann::ordered_json json =
      report::result_to_json(pipeline::recognize_cloud(points, grid, config::PipelineConfig{}, "cloud", &pool));
  json.erase("timings_ms");
  return json.dump();
}

void expect_same_for_1_2_3_threads(const PointList& points, const GridLayout& grid, std::size_t objects) {
  const std::string one = answer(points, grid, 1);
  ASSERT_EQ(nlohmann::json::parse(one)["objects"].size(), objects) << one;
  EXPECT_EQ(answer(points, grid, 2), one);
  EXPECT_EQ(answer(points, grid, 3), one);
}

TEST(RecognitionThreads, NoisySolidsGiveTheSameAnswer) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, at(0, 0, 0, 0.3)),
      synth::make_solid(synth::ShapeKind::cylinder, {0.8, 2.0}, at(0, 0, 0, 1.1)),
      synth::make_solid(synth::ShapeKind::cone, {1.0, 2.5}, at(0, 0, 0, 0.7)),
      synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(0, 0, 0, 0.0)),
  };
  for (std::size_t i = 0; i < solids.size(); ++i) {
    synth::CloudOptions opts;
    opts.points = 40000;
    opts.noise_sigma = 0.005;
    opts.outlier_fraction = 0.01;
    const auto cloud = synth::make_synthetic_cloud({solids[i]}, opts, 11 + i);
    SCOPED_TRACE(synth::to_string(solids[i].kind));
    expect_same_for_1_2_3_threads(cloud.points, GridLayout{}, 1);
  }
}

TEST(RecognitionThreads, ASceneOfSeveralObjectsGivesTheSameAnswer) {
  const std::vector<synth::SolidSpec> solids = {
      synth::make_solid(synth::ShapeKind::box, {3, 2, 1}, at(0, 0, 0, 0.3)),
      synth::make_solid(synth::ShapeKind::cylinder, {0.8, 2.0}, at(6, 0, 0, 1.1)),
      synth::make_solid(synth::ShapeKind::sphere, {1.0}, at(0, 6, 1, 0.0)),
      synth::make_solid(synth::ShapeKind::cone, {1.0, 2.0}, at(6, 6, 0, 0.4)),
  };
  synth::CloudOptions opts;
  opts.points = 80000;
  opts.noise_sigma = 0.003;
  const auto cloud = synth::make_synthetic_cloud(solids, opts, 5);
  expect_same_for_1_2_3_threads(cloud.points, GridLayout{}, 4);
}

TEST(RecognitionThreads, KinectFramesGiveTheSameAnswer) {
  const auto dir = testing::shared_data_path("real/mosd_learn");
  CLOUDSHAPE_REQUIRE_SHARED_DATA(dir);
  // Two boxes; three cans (the organized-graph path, several objects each).
  for (const auto& [name, objects] : std::vector<std::pair<std::string, std::size_t>>{{"learn0.pcd", 2}, {"learn40.pcd", 3}}) {
    SCOPED_TRACE(name);
    const io::CloudFile cloud = io::read_cloud((dir / name).string());
    expect_same_for_1_2_3_threads(cloud.points, cloud.grid, objects);
  }
}

}  // namespace
}  // namespace cloudshape
