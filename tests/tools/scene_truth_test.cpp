// Scene truth files and sidecars: the committed mOSD learn truth says what SOURCES.md says, and
// every malformed file is refused with a message naming it and the fault.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>

#include "scene_truth.hpp"

namespace cloudshape::bench {
namespace {

namespace fs = std::filesystem;

class SceneTruthFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "cloudshape-scene-truth-XXXXXX").string();
    ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  // The TruthError message of loading `text` as a truth file (empty when it loads).
  std::string truth_error(const std::string& text) {
    const std::string path = write("t.json", text);
    try {
      load_truth_file(path);
    } catch (const TruthError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      return e.what();
    }
    return {};
  }

  std::string sidecar_error(const std::string& text) {
    const std::string path = write("s.truth.json", text);
    try {
      load_sidecar(path, "x");
    } catch (const TruthError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      return e.what();
    }
    return {};
  }

  fs::path dir_;
};

TEST_F(SceneTruthFiles, MosdLearnTruthFollowsSourcesMd) {
  const TruthFile t = load_truth_file(CLOUDSHAPE_SCENE_TRUTH);
  EXPECT_EQ(t.category_order,
            (std::vector<std::string>{"boxes", "stacked_boxes", "occluded", "cylindric"}));
  ASSERT_EQ(t.scene_category.size(), 45u);
  const auto shapes = [&](int n) {
    return t.scene("learn" + std::to_string(n) + ".pcd")->default_shapes;
  };
  for (int n = 0; n <= 24; ++n) EXPECT_EQ(shapes(n), std::vector<std::string>{"box"}) << n;
  for (int n = 25; n <= 32; ++n)
    EXPECT_EQ(shapes(n), (std::vector<std::string>{"box", "cylinder"})) << n;
  for (int n = 33; n <= 44; ++n) EXPECT_EQ(shapes(n), std::vector<std::string>{"cylinder"}) << n;
  EXPECT_EQ(t.scene("learn16.pcd")->category, "boxes");
  EXPECT_EQ(t.scene("learn17.pcd")->category, "stacked_boxes");
  EXPECT_FALSE(t.scene("learn45.pcd").has_value());
}

TEST_F(SceneTruthFiles, MalformedTruthFilesAreRefusedWithTheFault) {
  EXPECT_NE(truth_error("{\"categories\": ").find("not valid JSON"), std::string::npos);
  EXPECT_NE(truth_error("[]").find("expected a JSON object"), std::string::npos);
  EXPECT_NE(truth_error("{\"scenes\": {\"a.pcd\": \"x\"}}").find("no \"categories\""),
            std::string::npos);
  EXPECT_NE(truth_error("{\"categories\": {\"x\": \"cyliner\"}, \"scenes\": {\"a.pcd\": \"x\"}}")
                .find("unknown shape 'cyliner'"),
            std::string::npos);
  EXPECT_NE(truth_error("{\"categories\": {\"x\": []}, \"scenes\": {\"a.pcd\": \"x\"}}")
                .find("no shape given"),
            std::string::npos);
  EXPECT_NE(truth_error("{\"categories\": {\"x\": \"box\"}, \"scenes\": {\"a.pcd\": \"y\"}}")
                .find("category 'y' is not in"),
            std::string::npos);
  EXPECT_NE(
      truth_error("{\"categories\": {\"x\": \"box\"}, \"scenes\": {}}").find("lists no scene"),
      std::string::npos);
  EXPECT_EQ(truth_error("{\"categories\": {\"x\": \"box\"}, \"scenes\": {\"a.pcd\": \"x\"}}"), "");
  try {
    load_truth_file((dir_ / "absent.json").string());
    FAIL() << "an absent file loaded";
  } catch (const TruthError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be opened"), std::string::npos) << e.what();
  }
}

TEST_F(SceneTruthFiles, SidecarGivesEachObjectItsShapes) {
  const std::string path =
      write("scene.truth.json",
            R"({"category": "touching", "groups": {"20": "box", "30": ["cylinder", "box"],)"
            R"( "31": ["box", "cylinder"]}})");
  const SceneTruth t = load_sidecar(path, "fallback");
  EXPECT_EQ(t.category, "touching");
  EXPECT_EQ(t.accepted_shapes(2), std::vector<std::string>{"box"});
  EXPECT_EQ(t.accepted_shapes(3), (std::vector<std::string>{"box", "cylinder"}));
  EXPECT_TRUE(t.accepted_shapes(4).empty());
  EXPECT_EQ(
      load_sidecar(write("b.truth.json", R"({"groups": {"20": "box"}})"), "fallback").category,
      "fallback");
  EXPECT_EQ(sidecar_path("/a/b/learn3.pcd"), "/a/b/learn3.truth.json");
}

TEST_F(SceneTruthFiles, MalformedSidecarsAreRefusedWithTheFault) {
  EXPECT_NE(sidecar_error(R"({"groups": {"20": "box", "21": "cylinder"}})")
                .find("labels 20 and 21 are parts of one object but give different shapes"),
            std::string::npos);
  EXPECT_NE(sidecar_error(R"({"groups": {"5": "box"}})").find("label 5 is not an object label"),
            std::string::npos);
  EXPECT_NE(sidecar_error(R"({"groups": {"2x": "box"}})").find("'2x' is not a label number"),
            std::string::npos);
  EXPECT_NE(sidecar_error(R"({"groups": {}})").find("lists no label"), std::string::npos);
  EXPECT_NE(sidecar_error(R"({"groups": {"20": 3}})").find("expected a shape name"),
            std::string::npos);
}

}  // namespace
}  // namespace cloudshape::bench
