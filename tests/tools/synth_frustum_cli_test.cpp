// `cloudshape-synth shape --shape frustum` end to end: the cloud and its ground truth come out,
// and `cloudshape-recognize` finds that frustum (radii and height within 2%, the signed axis).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "process.hpp"

namespace cloudshape {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

TEST(SynthFrustumCli, WholeAndNoisyIsRecognisedAsThatFrustum) {
  const fs::path cloud = fs::temp_directory_path() / ("cloudshape_frustum_" + std::to_string(getpid()) + ".pcd");
  const auto synth = testing::run_process({CLOUDSHAPE_SYNTH_BIN, "shape", "--shape", "frustum", "--dims", "40,25,60",
                                           "--random-pose", "--noise", "0.005", "--points", "20000", "--seed", "3",
                                           "-o", cloud.string()});
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  fs::path truth_path = cloud;
  truth_path.replace_extension(".json");
  std::ifstream truth_file(truth_path);
  ASSERT_TRUE(truth_file) << truth_path;
  const Json truth = Json::parse(truth_file);
  const Json& t = truth.at("objects").at(0);
  EXPECT_EQ(t.at("shape"), "frustum");
  EXPECT_EQ(t.at("dimensions").at("top_radius").get<double>(), 25.0);

  const auto recognized = testing::run_process({CLOUDSHAPE_RECOGNIZE_BIN, cloud.string()});
  fs::remove(cloud);
  fs::remove(truth_path);
  ASSERT_EQ(recognized.exit_code, 0) << recognized.err;
  const Json r = Json::parse(recognized.out);
  ASSERT_EQ(r.at("objects").size(), 1u) << recognized.out;
  const Json& o = r.at("objects").at(0);
  ASSERT_EQ(o.at("shape"), "frustum") << recognized.out;
  EXPECT_NEAR(o.at("dimensions").at("radius").get<double>(), 40.0, 0.8);
  EXPECT_NEAR(o.at("dimensions").at("top_radius").get<double>(), 25.0, 0.8);
  EXPECT_NEAR(o.at("dimensions").at("height").get<double>(), 60.0, 1.2);
  double dot = 0.0;
  for (int k = 0; k < 3; ++k)
    dot += o.at("pose").at("axes").at(0).at(k).get<double>() * t.at("pose").at("axes").at(0).at(k).get<double>();
  EXPECT_GT(dot, std::cos(2.0 * 3.14159265358979 / 180.0));
  EXPECT_TRUE(o.contains("extent"));
}

}  // namespace
}  // namespace cloudshape
