// config/pipeline.yaml: in step with the built-in defaults, and strict about what it accepts.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <type_traits>
#include <vector>
#include <unistd.h>

#include "config/config_fields.hpp"
#include "config/pipeline_config.hpp"

namespace cloudshape::config {
namespace {

std::string as_text(double value) { return std::to_string(value); }
std::string as_text(const std::string& value) { return "'" + value + "'"; }
std::string as_text(const std::vector<std::string>& values) {
  std::string out = "[";
  for (const std::string& v : values) out += as_text(v) + ",";
  return out + "]";
}

std::map<std::string, std::string> flatten(PipelineConfig cfg) {
  std::map<std::string, std::string> out;
  visit_sections(cfg, [&](const char* section, auto& s) {
    visit_fields(s, [&](const char* key, auto& value) {
      using T = std::decay_t<decltype(value)>;
      if constexpr (std::is_arithmetic_v<T>) {
        out[std::string(section) + "." + key] = as_text(static_cast<double>(value));
      } else {
        out[std::string(section) + "." + key] = as_text(value);
      }
    });
  });
  return out;
}

std::string write_temp(const std::string& text) {
  // ctest runs each test in its own process, in parallel: the pid keeps names apart.
  static int counter = 0;
  const auto path = std::filesystem::temp_directory_path() /
                    ("cloudshape_cfg_" + std::to_string(::getpid()) + "_" +
                     std::to_string(counter++) + ".yaml");
  std::ofstream(path) << text;
  return path.string();
}

std::string error_of(const std::string& yaml) {
  const std::string path = write_temp(yaml);
  try {
    load_pipeline_config(path);
  } catch (const ConfigError& e) {
    std::filesystem::remove(path);
    return e.what();
  }
  std::filesystem::remove(path);
  return {};
}

TEST(PipelineConfig, ShippedFileListsEveryParameterWithItsDefault) {
  const auto from_file = flatten(load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML));
  const auto defaults = flatten(PipelineConfig{});
  EXPECT_EQ(from_file, defaults);
  // Every key is spelled out in the file, so none is silently taken from the code.
  std::ifstream in(CLOUDSHAPE_PIPELINE_YAML);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  for (const auto& [key, value] : defaults) {
    const std::string leaf = key.substr(key.find('.') + 1) + ":";
    EXPECT_NE(text.find(leaf), std::string::npos) << key << " is missing from pipeline.yaml";
  }
}

TEST(PipelineConfig, AbsentKeysKeepDefaults) {
  const std::string path = write_temp("planes:\n  fine_threshold: 1.25\n");
  const PipelineConfig cfg = load_pipeline_config(path);
  std::filesystem::remove(path);
  EXPECT_DOUBLE_EQ(cfg.planes.fine_threshold, 1.25);
  EXPECT_DOUBLE_EQ(cfg.planes.coarse_threshold, PlanesConfig{}.coarse_threshold);
}

TEST(PipelineConfig, UnknownKeyIsRejectedByName) {
  const std::string msg = error_of("planes:\n  fine_treshold: 1.0\n");
  EXPECT_NE(msg.find("planes.fine_treshold"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown parameter"), std::string::npos) << msg;
}

TEST(PipelineConfig, UnknownSectionIsRejected) {
  EXPECT_NE(error_of("plane:\n  fine_threshold: 1.0\n").find("unknown section"), std::string::npos);
}

TEST(PipelineConfig, WrongTypesAndNegativeValuesAreRejected) {
  EXPECT_NE(error_of("planes:\n  fine_threshold: abc\n").find("planes.fine_threshold"), std::string::npos);
  EXPECT_NE(error_of("planes:\n  max_planes: -3\n").find(">= 0"), std::string::npos);
  EXPECT_NE(error_of("preprocess:\n  smoothing: maybe\n").find("true/false"), std::string::npos);
}

TEST(PipelineConfig, Ros2TopicsAndNames) {
  const std::string path = write_temp(
      "ros2:\n  input_topics: [/camera/depth/points, /lidar/points]\n  markers_topic: \"\"\n"
      "  file_frame_id: map\n");
  const PipelineConfig cfg = load_pipeline_config(path);
  std::filesystem::remove(path);
  EXPECT_EQ(cfg.ros2.input_topics, (std::vector<std::string>{"/camera/depth/points", "/lidar/points"}));
  EXPECT_EQ(cfg.ros2.markers_topic, "");
  EXPECT_EQ(cfg.ros2.file_frame_id, "map");
  EXPECT_EQ(cfg.ros2.detections_topic, Ros2Config{}.detections_topic);
  EXPECT_NE(error_of("ros2:\n  input_topics: /camera/depth/points\n").find("ros2.input_topics: expected a list"),
            std::string::npos);
  EXPECT_NE(error_of("ros2:\n  input_topics: [[a]]\n").find("ros2.input_topics[0]"), std::string::npos);
  EXPECT_NE(error_of("ros2:\n  markers_topic: [a]\n").find("ros2.markers_topic: expected a single value"),
            std::string::npos);
}

TEST(PipelineConfig, MissingFileAndBrokenYamlNameTheFile) {
  try {
    load_pipeline_config("/nonexistent/pipeline.yaml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/pipeline.yaml"), std::string::npos);
  }
  EXPECT_NE(error_of("planes: [unclosed\n").find("line"), std::string::npos);
}

}  // namespace
}  // namespace cloudshape::config
