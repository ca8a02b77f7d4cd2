// Reading and checking scene truth files and sidecars (forms in scene_truth.hpp).
// Strict on purpose: a typo in a shape or category would otherwise score every object wrong.
#include "scene_truth.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace cloudshape::bench {

namespace {

using Json = nlohmann::ordered_json;

// INTERFACE.md's shape names (prism and frustum included).
const std::vector<std::string>& known_shapes() {
  static const std::vector<std::string> names = {"box",   "tetrahedron", "pentagonal_prism",
                                                 "cone",  "cylinder",    "sphere",
                                                 "prism", "frustum",     "unknown"};
  return names;
}

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw TruthError("truth file " + path + ": " + problem);
}

Json parse_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return Json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    fail(path, std::string("not valid JSON (") + e.what() + ")");
  }
}

// One shape name or a non-empty list of them, each a known shape.
std::vector<std::string> shapes_of(const Json& j, const std::string& path,
                                   const std::string& what) {
  std::vector<std::string> shapes;
  if (j.is_string()) {
    shapes.push_back(j.get<std::string>());
  } else if (j.is_array()) {
    for (const auto& s : j) {
      if (!s.is_string()) fail(path, what + ": shapes must be strings");
      shapes.push_back(s.get<std::string>());
    }
  } else {
    fail(path, what + ": expected a shape name or a list of them");
  }
  if (shapes.empty()) fail(path, what + ": no shape given");
  for (const auto& s : shapes) {
    const auto& known = known_shapes();
    if (std::find(known.begin(), known.end(), s) == known.end())
      fail(path, what + ": unknown shape '" + s + "'");
  }
  return shapes;
}

const Json& member(const Json& j, const char* key, const std::string& path) {
  if (!j.contains(key)) fail(path, std::string("no \"") + key + "\" member");
  const Json& m = j.at(key);
  if (!m.is_object()) fail(path, std::string("\"") + key + "\" must be an object");
  return m;
}

std::uint32_t parse_label(const std::string& key, const std::string& path) {
  std::size_t used = 0;
  unsigned long value = 0;
  try {
    value = std::stoul(key, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != key.size() || value > 0xFFFFFFFFul)
    fail(path, "groups: '" + key + "' is not a label number");
  const auto label = static_cast<std::uint32_t>(value);
  if (!is_object_label(label))
    fail(path, "groups: label " + key +
                   " is not an object label (objects are >= 20; 1-9 are "
                   "the table, 0 invalid)");
  return label;
}

}  // namespace

const std::vector<std::string>& SceneTruth::accepted_shapes(std::uint32_t object) const {
  const auto it = object_shapes.find(object);
  return it != object_shapes.end() ? it->second : default_shapes;
}

std::optional<SceneTruth> TruthFile::scene(const std::string& file_name) const {
  const auto it = scene_category.find(file_name);
  if (it == scene_category.end()) return std::nullopt;
  SceneTruth t;
  t.category = it->second;
  t.default_shapes = categories.at(it->second);
  return t;
}

TruthFile load_truth_file(const std::string& path) {
  const Json j = parse_file(path);
  if (!j.is_object()) fail(path, "expected a JSON object");
  TruthFile truth;
  truth.path = path;
  for (const auto& [name, shapes] : member(j, "categories", path).items()) {
    truth.category_order.push_back(name);
    truth.categories[name] = shapes_of(shapes, path, "category '" + name + "'");
  }
  for (const auto& [scene, category] : member(j, "scenes", path).items()) {
    if (!category.is_string()) fail(path, "scene '" + scene + "': the category must be a string");
    const std::string name = category.get<std::string>();
    if (truth.categories.count(name) == 0)
      fail(path, "scene '" + scene + "': category '" + name + "' is not in \"categories\"");
    truth.scene_category[scene] = name;
  }
  if (truth.scene_category.empty()) fail(path, "\"scenes\" lists no scene");
  return truth;
}

SceneTruth load_sidecar(const std::string& path, const std::string& fallback_category) {
  const Json j = parse_file(path);
  if (!j.is_object()) fail(path, "expected a JSON object");
  SceneTruth t;
  t.category = fallback_category;
  if (j.contains("category")) {
    if (!j.at("category").is_string()) fail(path, "\"category\" must be a string");
    t.category = j.at("category").get<std::string>();
  }
  std::map<std::uint32_t, std::uint32_t> first_label;  // object -> the label that set its shapes
  for (const auto& [key, shapes] : member(j, "groups", path).items()) {
    const std::uint32_t label = parse_label(key, path);
    const std::uint32_t object = object_of_label(label);
    std::vector<std::string> accepted = shapes_of(shapes, path, "label " + key);
    std::sort(accepted.begin(), accepted.end());
    const auto [it, added] = t.object_shapes.emplace(object, accepted);
    if (!added && it->second != accepted)
      fail(path, "labels " + std::to_string(first_label[object]) + " and " + key +
                     " are parts of one object but give different shapes");
    first_label.emplace(object, label);
  }
  if (t.object_shapes.empty()) fail(path, "\"groups\" lists no label");
  return t;
}

std::string sidecar_path(const std::string& scene_path) {
  std::filesystem::path p(scene_path);
  p.replace_extension(".truth.json");
  return p.string();
}

}  // namespace cloudshape::bench
