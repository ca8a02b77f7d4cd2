// Scene truth documents. Labels name objects in the relations so a reader needs no indices.
#include "synth/scene_truth_json.hpp"

#include <cmath>
#include <map>

#include "synth/ground_truth_json.hpp"

namespace cloudshape::synth {

namespace {

nlohmann::json to_array(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

std::map<std::uint32_t, std::size_t> points_per_label(const RangeImage& image) {
  std::map<std::uint32_t, std::size_t> count;
  for (std::size_t i = 0; i < image.points.size(); ++i)
    if (image.labels[i] != 0 && std::isfinite(image.points[i].x())) ++count[image.labels[i]];
  return count;
}

}  // namespace

nlohmann::json scene_truth_json(const std::string& source, const SceneRecipe& recipe,
                                const GeneratedScene& generated, const Scene& scene,
                                const RangeImage& image, const nlohmann::json& sensor) {
  const auto count = points_per_label(image);
  std::size_t points = 0;
  for (const auto& [label, n] : count) points += n;
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& o : scene.objects) {
    nlohmann::json j = solid_to_json(o.solid);
    j["partial"] = true;
    j["label"] = o.label;
    j["visible_points"] = count.count(o.label) ? count.at(o.label) : 0;
    objects.push_back(std::move(j));
  }
  nlohmann::json structure = nlohmann::json::array();
  for (const auto& r : scene.structure)
    structure.push_back({{"kind", r.kind},
                         {"label", r.label},
                         {"center", to_array(r.center)},
                         {"normal", to_array(r.normal())},
                         {"size", {2.0 * r.half_u, 2.0 * r.half_v}},
                         {"visible_points", count.count(r.label) ? count.at(r.label) : 0}});
  const auto label_pairs = [&](const std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [a, b] : pairs)
      list.push_back({scene.objects[a].label, scene.objects[b].label});
    return list;
  };
  nlohmann::json against = nlohmann::json::array();
  for (const auto& [object, wall] : generated.against_wall)
    against.push_back({scene.objects[object].label, wall});
  return {{"source", source},
          {"layout", to_string(recipe.layout)},
          {"seed", recipe.seed},
          {"scale", recipe.scale},
          {"points", points},
          {"sensor", sensor},
          {"view", {0.0, 0.0, 0.0}},
          {"objects", objects},
          {"structure", structure},
          {"touching", label_pairs(generated.touching)},
          {"stacked", label_pairs(generated.stacked)},
          {"against_wall", against}};
}

nlohmann::json scene_groups_json(const Scene& scene, const RangeImage& image) {
  const auto count = points_per_label(image);
  nlohmann::json groups = nlohmann::json::object();
  for (const auto& o : scene.objects)
    if (count.count(o.label)) groups[std::to_string(o.label)] = to_string(o.solid.kind);
  return {{"groups", groups}};
}

}  // namespace cloudshape::synth
