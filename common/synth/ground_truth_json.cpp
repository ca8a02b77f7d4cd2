#include "synth/ground_truth_json.hpp"

#include <stdexcept>

namespace cloudshape::synth {

namespace {

nlohmann::json to_array(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Eigen::Vector3d vector_from(const nlohmann::json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 3)
    throw std::invalid_argument(what + " must be an array of 3 numbers");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!j[i].is_number()) throw std::invalid_argument(what + " must be an array of 3 numbers");
    v[i] = j[i].get<double>();
  }
  return v;
}

const nlohmann::json& field(const nlohmann::json& object, const char* name) {
  if (!object.is_object() || !object.contains(name))
    throw std::invalid_argument(std::string("missing field '") + name + "'");
  return object.at(name);
}

}  // namespace

nlohmann::json solid_to_json(const SolidSpec& spec) {
  nlohmann::json dims = nlohmann::json::object();
  for (const auto& [name, value] : spec.dimensions) dims[name] = value;
  nlohmann::json axes = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) axes.push_back(to_array(spec.pose.axes.row(i).transpose()));
  return {{"shape", to_string(spec.kind)},
          {"dimensions", dims},
          {"pose", {{"center", to_array(spec.pose.center)}, {"axes", axes}}}};
}

SolidSpec solid_from_json(const nlohmann::json& object) {
  const auto& shape = field(object, "shape");
  if (!shape.is_string()) throw std::invalid_argument("'shape' must be a string");
  const auto kind = shape_kind_from_string(shape.get<std::string>());
  if (!kind) throw std::invalid_argument("unsupported shape '" + shape.get<std::string>() + "'");

  const auto& dims = field(object, "dimensions");
  std::vector<double> values;
  for (const auto& name : dimension_names(*kind)) {
    const auto& value = field(dims, name.c_str());
    if (!value.is_number())
      throw std::invalid_argument("dimension '" + name + "' must be a number");
    values.push_back(value.get<double>());
  }

  const auto& pose_json = field(object, "pose");
  Pose pose;
  pose.center = vector_from(field(pose_json, "center"), "pose.center");
  const auto& axes = field(pose_json, "axes");
  if (!axes.is_array() || axes.size() != 3)
    throw std::invalid_argument("pose.axes must be an array of 3 vectors");
  for (int i = 0; i < 3; ++i)
    pose.axes.row(i) = vector_from(axes[i], "pose.axes[" + std::to_string(i) + "]").transpose();

  // make_solid validates; for a box it also re-sorts, which only reorders axes with their
  // dimensions and so leaves the described solid unchanged.
  return make_solid(*kind, values, pose);
}

nlohmann::json ground_truth_json(const std::string& source, const std::vector<SolidSpec>& objects,
                                 const GenerationInfo& info) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& spec : objects) {
    nlohmann::json o = solid_to_json(spec);
    if (info.view) o["partial"] = true;
    list.push_back(std::move(o));
  }
  nlohmann::json doc = {{"source", source},
                        {"objects", list},
                        {"points", info.points},
                        {"seed", info.seed},
                        {"noise_sigma", info.noise_sigma},
                        {"outlier_fraction", info.outlier_fraction},
                        {"outliers", info.outliers}};
  if (info.view) doc["view"] = to_array(*info.view);
  if (info.density_falloff_from) doc["density_falloff_from"] = to_array(*info.density_falloff_from);
  if (info.patchiness > 0.0) doc["patchiness"] = info.patchiness;
  return doc;
}

std::vector<SolidSpec> solids_from_ground_truth(const nlohmann::json& document) {
  const auto& objects = field(document, "objects");
  if (!objects.is_array()) throw std::invalid_argument("'objects' must be an array");
  std::vector<SolidSpec> specs;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    try {
      specs.push_back(solid_from_json(objects[i]));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("objects[" + std::to_string(i) + "]: " + e.what());
    }
  }
  return specs;
}

}  // namespace cloudshape::synth
