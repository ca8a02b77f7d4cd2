#include "report/result_json.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace cloudshape::report {
namespace {

template <class Json>
Json vec3_to_json(const Eigen::Vector3d& v) {
  return Json::array({v.x(), v.y(), v.z()});
}

template <class Json>
Json axes_to_json(const Eigen::Matrix3d& axes) {
  Json out = Json::array();
  for (int i = 0; i < 3; ++i) out.push_back(vec3_to_json<Json>(axes.row(i).transpose()));
  return out;
}

template <class Json>
Json object_to_json(const pipeline::ObjectResult& o) {
  Json obj = Json::object();
  obj["shape"] = o.shape;
  obj["confidence"] = o.confidence;
  Json dims = Json::object();
  for (const auto& [name, value] : o.dimensions) {
    // A count, not a length: written as the integer it is.
    if (name == "sides") dims[name] = static_cast<std::int64_t>(std::llround(value));
    else dims[name] = value;
  }
  obj["dimensions"] = std::move(dims);
  Json pose = Json::object();
  pose["center"] = vec3_to_json<Json>(o.center);
  pose["axes"] = axes_to_json<Json>(o.axes);
  obj["pose"] = std::move(pose);
  obj["partial"] = o.partial;
  Json kp = Json::object();
  kp["corner"] = o.keypoints.corner;
  kp["edge"] = o.keypoints.edge;
  kp["border"] = o.keypoints.border;
  obj["keypoints"] = std::move(kp);
  Json extent = Json::object();
  extent["center"] = vec3_to_json<Json>(o.extent.center);
  extent["axes"] = axes_to_json<Json>(o.extent.axes);
  extent["size"] = vec3_to_json<Json>(o.extent.size);
  obj["extent"] = std::move(extent);
  if (!o.polygon.empty()) {
    Json polygon = Json::array();
    for (const Eigen::Vector2d& q : o.polygon) polygon.push_back(Json::array({q.x(), q.y()}));
    obj["polygon"] = std::move(polygon);
  }
  if (!o.vertices.empty()) {
    Json vertices = Json::array();
    for (const Eigen::Vector3d& v : o.vertices) vertices.push_back(vec3_to_json<Json>(v));
    obj["vertices"] = std::move(vertices);
    obj["regular"] = o.regular;
  }
  if (!o.reason.empty()) obj["reason"] = o.reason;
  return obj;
}

// ---- parsing -------------------------------------------------------------------------------

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
  throw ResultFormatError("result JSON: " + (where.empty() ? std::string("top level") : where) +
                          ": " + problem);
}

std::string join(const std::string& where, const std::string& key) {
  return where.empty() ? key : where + "." + key;
}

template <class Json>
const Json& member(const Json& obj, const std::string& key, const std::string& where) {
  if (!obj.is_object()) fail(where, "expected an object");
  auto it = obj.find(key);
  if (it == obj.end()) fail(join(where, key), "missing");
  return *it;
}

template <class Json>
double number(const Json& j, const std::string& where) {
  if (!j.is_number()) fail(where, "expected a number, got " + std::string(j.type_name()));
  return j.template get<double>();
}

template <class Json>
std::uint64_t count(const Json& j, const std::string& where) {
  if (j.is_number_unsigned()) return j.template get<std::uint64_t>();
  if (j.is_number_integer()) {
    if (j.template get<std::int64_t>() < 0) fail(where, "expected a count >= 0");
    return j.template get<std::uint64_t>();
  }
  fail(where, "expected a non-negative integer, got " + std::string(j.type_name()));
}

template <class Json>
int small_count(const Json& j, const std::string& where) {
  const std::uint64_t n = count(j, where);
  if (n > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) fail(where, "too large");
  return static_cast<int>(n);
}

template <class Json>
std::string string(const Json& j, const std::string& where) {
  if (!j.is_string()) fail(where, "expected a string, got " + std::string(j.type_name()));
  return j.template get<std::string>();
}

template <class Json>
Eigen::Vector3d vec3(const Json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3) fail(where, "expected an array of 3 numbers");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = number(j[i], where + "[" + std::to_string(i) + "]");
  return v;
}

template <class Json>
Eigen::Matrix3d axes3(const Json& axes, const std::string& awhere) {
  if (!axes.is_array() || axes.size() != 3) fail(awhere, "expected 3 arrays of 3 numbers");
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i) m.row(i) = vec3(axes[i], awhere + "[" + std::to_string(i) + "]").transpose();
  return m;
}

template <class Json>
const Json& array_member(const Json& obj, const std::string& key, const std::string& where) {
  const Json& a = member(obj, key, where);
  if (!a.is_array()) fail(join(where, key), "expected an array");
  return a;
}

template <class Json>
pipeline::ObjectResult parse_object(const Json& j, const std::string& where) {
  if (!j.is_object()) fail(where, "expected an object");
  pipeline::ObjectResult o;
  o.shape = string(member(j, "shape", where), join(where, "shape"));
  o.confidence = number(member(j, "confidence", where), join(where, "confidence"));

  const std::string dwhere = join(where, "dimensions");
  const Json& dims = member(j, "dimensions", where);
  if (!dims.is_object()) fail(dwhere, "expected an object");
  const auto& canonical = dimension_names(o.shape);
  for (const auto& name : canonical) {
    auto it = dims.find(name);
    if (it != dims.end()) o.dimensions.emplace_back(name, number(*it, join(dwhere, name)));
  }
  for (auto it = dims.begin(); it != dims.end(); ++it) {
    bool is_canonical = false;
    for (const auto& name : canonical) is_canonical = is_canonical || name == it.key();
    if (!is_canonical) o.dimensions.emplace_back(it.key(), number(*it, join(dwhere, it.key())));
  }

  const std::string pwhere = join(where, "pose");
  const Json& pose = member(j, "pose", where);
  o.center = vec3(member(pose, "center", pwhere), join(pwhere, "center"));
  o.axes = axes3(member(pose, "axes", pwhere), join(pwhere, "axes"));

  const Json& partial = member(j, "partial", where);
  if (!partial.is_boolean()) fail(join(where, "partial"), "expected true or false");
  o.partial = partial.template get<bool>();

  const std::string kwhere = join(where, "keypoints");
  const Json& kp = member(j, "keypoints", where);
  o.keypoints.corner = small_count(member(kp, "corner", kwhere), join(kwhere, "corner"));
  o.keypoints.edge = small_count(member(kp, "edge", kwhere), join(kwhere, "edge"));
  o.keypoints.border = small_count(member(kp, "border", kwhere), join(kwhere, "border"));

  // Optional here so that results of producers older than these fields stay readable.
  if (j.contains("extent")) {
    const std::string ewhere = join(where, "extent");
    const Json& e = member(j, "extent", where);
    o.extent.center = vec3(member(e, "center", ewhere), join(ewhere, "center"));
    o.extent.axes = axes3(member(e, "axes", ewhere), join(ewhere, "axes"));
    o.extent.size = vec3(member(e, "size", ewhere), join(ewhere, "size"));
  }
  if (j.contains("polygon")) {
    const Json& polygon = array_member(j, "polygon", where);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const std::string pw = join(where, "polygon") + "[" + std::to_string(i) + "]";
      if (!polygon[i].is_array() || polygon[i].size() != 2) fail(pw, "expected an array of 2 numbers");
      o.polygon.emplace_back(number(polygon[i][0], pw + "[0]"), number(polygon[i][1], pw + "[1]"));
    }
  }
  if (j.contains("vertices")) {
    const Json& vertices = array_member(j, "vertices", where);
    for (std::size_t i = 0; i < vertices.size(); ++i)
      o.vertices.push_back(vec3(vertices[i], join(where, "vertices") + "[" + std::to_string(i) + "]"));
  }
  if (auto it = j.find("regular"); it != j.end()) {
    if (!it->is_boolean()) fail(join(where, "regular"), "expected true or false");
    o.regular = it->template get<bool>();
  }
  if (auto it = j.find("reason"); it != j.end()) o.reason = string(*it, join(where, "reason"));
  return o;
}

template <class Json>
pipeline::RecognitionResult parse_result(const Json& j) {
  if (!j.is_object()) fail("", "expected an object, got " + std::string(j.type_name()));
  pipeline::RecognitionResult r;
  r.source = string(member(j, "source", ""), "source");
  r.points_in = static_cast<std::size_t>(count(member(j, "points_in", ""), "points_in"));
  r.points_used = static_cast<std::size_t>(count(member(j, "points_used", ""), "points_used"));
  r.resolution = number(member(j, "resolution", ""), "resolution");

  const Json& objects = member(j, "objects", "");
  if (!objects.is_array()) fail("objects", "expected an array");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    r.objects.push_back(parse_object(objects[i], "objects[" + std::to_string(i) + "]"));
  }

  const Json& t = member(j, "timings_ms", "");
  const std::string tw = "timings_ms";
  r.timings.preprocess_ms = number(member(t, "preprocess", tw), join(tw, "preprocess"));
  r.timings.planes_ms = number(member(t, "planes", tw), join(tw, "planes"));
  r.timings.keypoints_ms = number(member(t, "keypoints", tw), join(tw, "keypoints"));
  r.timings.classify_ms = number(member(t, "classify", tw), join(tw, "classify"));
  r.timings.solve_ms = number(member(t, "solve", tw), join(tw, "solve"));
  r.timings.total_ms = number(member(t, "total", tw), join(tw, "total"));
  return r;
}

}  // namespace

double round_timing_ms(double ms) {
  if (!std::isfinite(ms)) return ms;
  return std::round(ms * 100.0) / 100.0;
}

const std::vector<std::string>& known_shape_names() {
  static const std::vector<std::string> names = {
      "box", "tetrahedron", "pentagonal_prism", "cone", "cylinder", "sphere", "unknown", "prism", "frustum"};
  return names;
}

const std::vector<std::string>& dimension_names(const std::string& shape) {
  static const std::unordered_map<std::string, std::vector<std::string>> table = {
      {"box", {"length", "width", "height"}},   {"tetrahedron", {"edge"}},
      {"pentagonal_prism", {"side", "height"}}, {"cone", {"radius", "height"}},
      {"cylinder", {"radius", "height"}},       {"sphere", {"radius"}},
      {"prism", {"height", "sides", "side"}},   {"frustum", {"radius", "top_radius", "height"}},
  };
  static const std::vector<std::string> none;
  auto it = table.find(shape);
  return it == table.end() ? none : it->second;
}

nlohmann::ordered_json result_to_json(const pipeline::RecognitionResult& r) {
  using Json = nlohmann::ordered_json;
  Json j = Json::object();
  j["source"] = r.source;
  j["points_in"] = static_cast<std::uint64_t>(r.points_in);
  j["points_used"] = static_cast<std::uint64_t>(r.points_used);
  j["resolution"] = r.resolution;
  Json objects = Json::array();
  for (const auto& o : r.objects) objects.push_back(object_to_json<Json>(o));
  j["objects"] = std::move(objects);
  Json t = Json::object();
  t["preprocess"] = round_timing_ms(r.timings.preprocess_ms);
  t["planes"] = round_timing_ms(r.timings.planes_ms);
  t["keypoints"] = round_timing_ms(r.timings.keypoints_ms);
  t["classify"] = round_timing_ms(r.timings.classify_ms);
  t["solve"] = round_timing_ms(r.timings.solve_ms);
  t["total"] = round_timing_ms(r.timings.total_ms);
  j["timings_ms"] = std::move(t);
  return j;
}

std::string result_to_json_line(const pipeline::RecognitionResult& result) {
  return result_to_json(result).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string result_to_json_pretty(const pipeline::RecognitionResult& result, int indent) {
  return result_to_json(result).dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

pipeline::RecognitionResult result_from_json(const nlohmann::json& json) {
  return parse_result(json);
}

pipeline::RecognitionResult result_from_json(const nlohmann::ordered_json& json) {
  return parse_result(json);
}

pipeline::RecognitionResult result_from_json_line(const std::string& line) {
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(line);
  } catch (const nlohmann::json::parse_error& e) {
    throw ResultFormatError(std::string("result JSON: not valid JSON: ") + e.what());
  }
  return parse_result(j);
}

}  // namespace cloudshape::report
