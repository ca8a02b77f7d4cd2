// Ground-truth JSON: schema of INTERFACE.md and a lossless round trip.
#include "synth/ground_truth_json.hpp"
#include "synth/random_solid.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

TEST(GroundTruthJson, RoundTripsThroughText) {
  std::mt19937_64 rng(51);
  std::vector<SolidSpec> solids;
  for (ShapeKind kind : all_shape_kinds()) solids.push_back(random_solid(kind, rng, 7.0));
  GenerationInfo info;
  info.points = 1234;
  info.seed = 51;
  info.noise_sigma = 0.01;
  const auto doc = nlohmann::json::parse(ground_truth_json("all.pcd", solids, info).dump());
  EXPECT_EQ(doc.at("source"), "all.pcd");
  EXPECT_EQ(doc.at("points"), 1234);
  EXPECT_EQ(doc.at("seed"), 51);
  EXPECT_FALSE(doc.contains("view"));
  const auto back = solids_from_ground_truth(doc);
  ASSERT_EQ(back.size(), solids.size());
  for (std::size_t i = 0; i < solids.size(); ++i) {
    EXPECT_EQ(back[i].kind, solids[i].kind);
    EXPECT_EQ(back[i].dimensions, solids[i].dimensions);
    EXPECT_EQ(back[i].pose.center, solids[i].pose.center);
    EXPECT_EQ(back[i].pose.axes, solids[i].pose.axes);
  }
}

TEST(GroundTruthJson, UsesTheRecognizerSchema) {
  const SolidSpec box = make_solid(ShapeKind::box, {30, 20, 10});
  GenerationInfo info;
  info.view = Eigen::Vector3d(0, 0, 100);
  const auto doc = ground_truth_json("box.pcd", {box}, info);
  const auto& o = doc.at("objects").at(0);
  EXPECT_EQ(o.at("shape"), "box");
  EXPECT_EQ(o.at("dimensions"),
            nlohmann::json({{"length", 30.0}, {"width", 20.0}, {"height", 10.0}}));
  EXPECT_EQ(o.at("pose").at("center"), nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_EQ(o.at("pose").at("axes"),
            nlohmann::json({{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}));
  EXPECT_EQ(o.at("partial"), true);
  EXPECT_EQ(doc.at("view"), nlohmann::json({0.0, 0.0, 100.0}));
}

TEST(GroundTruthJson, ParsesARecognizerLine) {
  const auto line = nlohmann::json::parse(R"({"source": "c.pcd", "objects": [
    {"shape": "cone", "confidence": 0.9, "dimensions": {"radius": 2, "height": 5},
     "pose": {"center": [1, 2, 3], "axes": [[0,0,1],[1,0,0],[0,1,0]]}, "partial": false}]})");
  const auto specs = solids_from_ground_truth(line);
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(specs[0].kind, ShapeKind::cone);
  EXPECT_EQ(dimension(specs[0], "height"), 5.0);
  EXPECT_EQ(specs[0].pose.axes.row(0), Eigen::RowVector3d(0, 0, 1));
}

TEST(GroundTruthJson, MalformedDocumentsThrowInvalidArgument) {
  const auto bad = [](const char* text) {
    EXPECT_THROW(solids_from_ground_truth(nlohmann::json::parse(text)), std::invalid_argument)
        << text;
  };
  bad(R"({})");
  bad(R"({"objects": [{"shape": "unknown", "dimensions": {}}]})");
  bad(R"({"objects": [{"shape": "sphere", "dimensions": {}, "pose": {"center": [0,0,0], "axes": [[1,0,0],[0,1,0],[0,0,1]]}}]})");
  bad(R"({"objects": [{"shape": "sphere", "dimensions": {"radius": 1}, "pose": {"center": [0,0], "axes": [[1,0,0],[0,1,0],[0,0,1]]}}]})");
  bad(R"({"objects": [{"shape": "sphere", "dimensions": {"radius": -1}, "pose": {"center": [0,0,0], "axes": [[1,0,0],[0,1,0],[0,0,1]]}}]})");
}

}  // namespace
}  // namespace cloudshape::synth
