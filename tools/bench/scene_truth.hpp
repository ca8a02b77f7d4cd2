// cloudshape-bench --scenes: what each labelled scene's objects should be, from a truth file
// (scene -> category -> accepted shapes) or a per-scene sidecar (<scene>.truth.json).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cloudshape::bench {

// Labels follow the Object Segmentation Database (shared/data/real/SOURCES.md, mosd_learn):
// 0 invalid, 1-9 the table (structure), >= 20 objects: label / 10 is the object, label % 10
// one of its geometrically disjoint parts. 10-19 carry no meaning there and count as invalid.
inline bool is_structure_label(std::uint32_t label) { return label >= 1 && label <= 9; }
inline bool is_object_label(std::uint32_t label) { return label >= 20; }
inline std::uint32_t object_of_label(std::uint32_t label) { return label / 10; }

struct SceneTruth {
  std::string category;
  std::vector<std::string> default_shapes;  // every object's accepted shapes (the category's)
  // Per object (label / 10), from a sidecar: replaces default_shapes for that object.
  std::map<std::uint32_t, std::vector<std::string>> object_shapes;

  // Empty when the truth says nothing about `object`.
  const std::vector<std::string>& accepted_shapes(std::uint32_t object) const;
};

// A truth file, e.g. tools/bench/mosd_learn.truth.json:
//   {"categories": {"boxes": ["box"], ...}, "scenes": {"learn0.pcd": "boxes", ...}}
// A category's shapes may be one string or a list; "description" is free text.
struct TruthFile {
  std::string path;
  std::vector<std::string> category_order;  // as the file lists them: the table's row order
  std::map<std::string, std::vector<std::string>> categories;
  std::map<std::string, std::string> scene_category;  // scene file name -> category

  std::optional<SceneTruth> scene(const std::string& file_name) const;
};

// Bad truth input: the message names the file and what is wrong with it.
class TruthError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws TruthError for a file that cannot be read, is not JSON, or breaks the form above
// (a scene naming an undeclared category, a category without shapes, ...).
TruthFile load_truth_file(const std::string& path);

// A sidecar: {"category": "touching", "groups": {"20": "box", "30": ["box", "cylinder"]}}.
// Keys are object labels (>= 20); the parts of one object (40, 41) must agree. "category" is
// optional (default `fallback_category`). Throws TruthError naming `path`.
SceneTruth load_sidecar(const std::string& path, const std::string& fallback_category);

// The sidecar path of a scene: learn0.pcd -> learn0.truth.json beside it.
std::string sidecar_path(const std::string& scene_path);

}  // namespace cloudshape::bench
