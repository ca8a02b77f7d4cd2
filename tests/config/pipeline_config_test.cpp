// config/pipeline.yaml: in step with the built-in defaults, and strict about what it accepts.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <unistd.h>

#include "config/config_fields.hpp"
#include "config/pipeline_config.hpp"

namespace cloudshape::config {
namespace {

std::map<std::string, double> flatten(PipelineConfig cfg) {
  std::map<std::string, double> out;
  visit_sections(cfg, [&](const char* section, auto& s) {
    visit_fields(s, [&](const char* key, auto& value) {
      out[std::string(section) + "." + key] = static_cast<double>(value);
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
