#include "config/pipeline_config.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <type_traits>
#include <vector>
#include <unistd.h>

#include "config/config_fields.hpp"

namespace cloudshape::config {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& where, const std::string& what) {
  throw ConfigError(path + ": " + where + ": " + what);
}

template <class T>
void read_value(const YAML::Node& node, const std::string& path, const std::string& key, T& out) {
  try {
    if (!node.IsScalar()) fail(path, key, "expected a single value");
    const T value = node.as<T>();
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(value) || value < 0.0) fail(path, key, "must be a finite number >= 0");
    } else if constexpr (std::is_same_v<T, std::int64_t>) {
      if (value < 0) fail(path, key, "must be an integer >= 0");
    }
    out = value;
  } catch (const YAML::Exception&) {
    fail(path, key, "cannot read '" + node.as<std::string>("?") + "' as " +
                        (std::is_same_v<T, bool> ? "true/false"
                         : std::is_floating_point_v<T> ? "a number"
                                                       : "an integer"));
  }
}

// A list of names (ros2.input_topics): a YAML sequence of single values, [] for none.
void read_value(const YAML::Node& node, const std::string& path, const std::string& key,
                std::vector<std::string>& out) {
  if (!node.IsSequence()) fail(path, key, "expected a list, e.g. [/camera/depth/points]");
  std::vector<std::string> values;
  for (std::size_t i = 0; i < node.size(); ++i) {
    if (!node[i].IsScalar()) fail(path, key + "[" + std::to_string(i) + "]", "expected a single value");
    values.push_back(node[i].as<std::string>());
  }
  out = std::move(values);
}

template <class Section>
void read_section(const YAML::Node& node, const std::string& path, const std::string& name,
                  Section& section) {
  if (!node.IsMap()) fail(path, name, "expected a mapping of parameter: value");
  std::set<std::string> known;
  visit_fields(section, [&](const char* key, auto& field) {
    known.insert(key);
    if (const YAML::Node value = node[key]) read_value(value, path, name + "." + key, field);
  });
  for (const auto& kv : node) {
    const auto key = kv.first.as<std::string>();
    if (!known.count(key)) fail(path, name + "." + key, "unknown parameter");
  }
}

}  // namespace

PipelineConfig load_pipeline_config(const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    fail(path, "file", "cannot be opened");
  } catch (const YAML::Exception& e) {
    fail(path, "line " + std::to_string(e.mark.line + 1), e.msg);
  }
  PipelineConfig cfg;
  if (root.IsNull()) return cfg;
  if (!root.IsMap()) fail(path, "top level", "expected a mapping of sections");
  std::set<std::string> known;
  visit_sections(cfg, [&](const char* name, auto& section) {
    known.insert(name);
    if (const YAML::Node node = root[name]) read_section(node, path, name, section);
  });
  for (const auto& kv : root) {
    const auto key = kv.first.as<std::string>();
    if (!known.count(key)) fail(path, key, "unknown section");
  }
  return cfg;
}

std::string default_pipeline_config_path() {
  namespace fs = std::filesystem;
  std::error_code ec;
  // build/bin/<tool> -> <repo>/config/pipeline.yaml, so a moved checkout still works.
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    for (const fs::path& candidate : {exe.parent_path() / "../../config/pipeline.yaml",
                                      exe.parent_path() / "../config/pipeline.yaml",
                                      exe.parent_path() / "../share/cloudshape/pipeline.yaml"}) {
      if (fs::exists(candidate, ec)) return fs::weakly_canonical(candidate, ec).string();
    }
  }
  const fs::path source = CLOUDSHAPE_SOURCE_CONFIG;
  if (fs::exists(source, ec)) return source.string();
  return {};
}

}  // namespace cloudshape::config
