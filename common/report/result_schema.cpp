// schema_problems(): the INTERFACE.md contract for one result object, checked key by key.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "report/result_json.hpp"

namespace cloudshape::report {
namespace {

using Json = nlohmann::ordered_json;

class Checker {
 public:
  std::vector<std::string> problems;

  void add(const std::string& where, const std::string& what) {
    problems.push_back((where.empty() ? std::string("top level") : where) + ": " + what);
  }

  // Keys exactly `required` in this order, then optionally the `optional` ones (in order).
  bool keys(const Json& j, const std::string& where, const std::vector<std::string>& required,
            const std::vector<std::string>& optional = {}) {
    if (!j.is_object()) {
      add(where, std::string("expected an object, got ") + j.type_name());
      return false;
    }
    std::vector<std::string> got;
    for (auto it = j.begin(); it != j.end(); ++it) got.push_back(it.key());
    std::vector<std::string> want = required;
    for (const auto& k : optional) {
      if (j.contains(k)) want.push_back(k);
    }
    if (got != want) add(where, "keys are [" + list(got) + "], expected [" + list(want) + "]");
    return true;
  }

  bool number(const Json& j, const std::string& where, double lo = -HUGE_VAL,
              double hi = HUGE_VAL) {
    if (!j.is_number()) {
      add(where, std::string("expected a number, got ") + j.type_name());
      return false;
    }
    const double v = j.get<double>();
    if (!std::isfinite(v) || v < lo || v > hi) {
      add(where, "value " + std::to_string(v) + " out of range [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
      return false;
    }
    return true;
  }

  bool count(const Json& j, const std::string& where) {
    if (!j.is_number_integer() || (!j.is_number_unsigned() && j.get<long long>() < 0)) {
      add(where, "expected an integer >= 0");
      return false;
    }
    return true;
  }

  bool vec3(const Json& j, const std::string& where, Eigen::Vector3d* out) {
    if (!j.is_array() || j.size() != 3) {
      add(where, "expected an array of 3 numbers");
      return false;
    }
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
      ok = number(j[i], where + "[" + std::to_string(i) + "]") && ok;
      if (ok && out) (*out)[i] = j[i].get<double>();
    }
    return ok;
  }

  void object(const Json& o, const std::string& w) {
    if (!keys(o, w, {"shape", "confidence", "dimensions", "pose", "partial", "keypoints", "extent"},
              {"polygon", "vertices", "regular", "reason"})) {
      return;
    }
    std::string shape;
    if (o.contains("shape")) {
      if (!o["shape"].is_string() || o["shape"].get<std::string>().empty()) {
        add(w + ".shape", "expected a non-empty string");
      } else {
        shape = o["shape"].get<std::string>();
        const bool lower = std::all_of(shape.begin(), shape.end(),
                                       [](char c) { return (c >= 'a' && c <= 'z') || c == '_'; });
        if (!lower) add(w + ".shape", "'" + shape + "' is not a lower_case name");
      }
    }
    if (o.contains("confidence")) number(o["confidence"], w + ".confidence", 0.0, 1.0);
    if (o.contains("dimensions")) dimensions(o["dimensions"], w + ".dimensions", shape);
    if (o.contains("pose")) pose(o["pose"], w + ".pose");
    if (o.contains("partial") && !o["partial"].is_boolean()) {
      add(w + ".partial", "expected true or false");
    }
    if (o.contains("keypoints") &&
        keys(o["keypoints"], w + ".keypoints", {"corner", "edge", "border"})) {
      for (const char* k : {"corner", "edge", "border"}) {
        if (o["keypoints"].contains(k)) count(o["keypoints"][k], w + ".keypoints." + k);
      }
    }
    if (o.contains("reason") && !o["reason"].is_string()) add(w + ".reason", "expected a string");
    if (o.contains("extent")) extent(o["extent"], w + ".extent");
    extras(o, w, shape);
  }

  // polygon belongs to a prism and only to it, vertices and regular to a tetrahedron.
  void extras(const Json& o, const std::string& w, const std::string& shape) {
    if ((shape == "prism") != o.contains("polygon"))
      add(w + ".polygon", shape == "prism" ? "a prism needs its polygon" : "only a prism has a polygon");
    for (const char* k : {"vertices", "regular"})
      if ((shape == "tetrahedron") != o.contains(k))
        add(w + "." + k, shape == "tetrahedron" ? "a tetrahedron needs it" : "only a tetrahedron has it");
    if (o.contains("polygon")) polygon(o["polygon"], w + ".polygon");
    if (o.contains("vertices")) {
      const Json& v = o["vertices"];
      if (!v.is_array() || v.size() != 4) add(w + ".vertices", "expected 4 points");
      else
        for (std::size_t i = 0; i < 4; ++i) vec3(v[i], w + ".vertices[" + std::to_string(i) + "]", nullptr);
    }
    if (o.contains("regular") && !o["regular"].is_boolean()) add(w + ".regular", "expected true or false");
  }

  // At least three [u, v] pairs, counter-clockwise (positive area), simple enough to have one.
  void polygon(const Json& p, const std::string& w) {
    if (!p.is_array() || p.size() < 3) {
      add(w, "expected at least 3 [u, v] pairs");
      return;
    }
    std::vector<Eigen::Vector2d> q;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::string iw = w + "[" + std::to_string(i) + "]";
      if (!p[i].is_array() || p[i].size() != 2) {
        add(iw, "expected [u, v]");
        return;
      }
      if (!number(p[i][0], iw + "[0]") || !number(p[i][1], iw + "[1]")) return;
      q.emplace_back(p[i][0].get<double>(), p[i][1].get<double>());
    }
    double area2 = 0.0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      const Eigen::Vector2d& a = q[i];
      const Eigen::Vector2d& b = q[(i + 1) % q.size()];
      area2 += a.x() * b.y() - a.y() * b.x();
    }
    if (!(area2 > 0.0)) add(w, "not counter-clockwise (signed area <= 0)");
  }

  void extent(const Json& e, const std::string& w) {
    if (!keys(e, w, {"center", "axes", "size"})) return;
    if (e.contains("center")) vec3(e["center"], w + ".center", nullptr);
    if (e.contains("axes")) axes(e["axes"], w + ".axes");
    Eigen::Vector3d size;
    if (e.contains("size") && vec3(e["size"], w + ".size", &size) && !(size.minCoeff() >= 0.0))
      add(w + ".size", "a size must be >= 0");
  }

  void dimensions(const Json& d, const std::string& w, const std::string& shape) {
    if (!d.is_object()) {
      add(w, "expected an object");
      return;
    }
    const bool known = std::find(known_shape_names().begin(), known_shape_names().end(), shape) !=
                       known_shape_names().end();
    if (shape == "prism") keys(d, w, {"height", "sides"}, {"side"});
    else if (known) keys(d, w, dimension_names(shape));
    if (shape == "prism" && d.contains("sides") &&
        (!d["sides"].is_number_integer() || d["sides"].get<long long>() < 3))
      add(w + ".sides", "expected an integer >= 3");
    for (auto it = d.begin(); it != d.end(); ++it) {
      if (number(it.value(), w + "." + it.key()) && it.value().get<double>() <= 0.0) {
        add(w + "." + it.key(), "a length must be > 0");
      }
    }
    if (shape == "box" && d.contains("length") && d.contains("width") && d.contains("height") &&
        d["length"].is_number() && d["width"].is_number() && d["height"].is_number()) {
      const double l = d["length"].get<double>(), wd = d["width"].get<double>(),
                   h = d["height"].get<double>();
      if (!(l >= wd && wd >= h)) add(w, "box needs length >= width >= height");
    }
  }

  void pose(const Json& p, const std::string& w) {
    if (!keys(p, w, {"center", "axes"})) return;
    if (p.contains("center")) vec3(p["center"], w + ".center", nullptr);
    if (p.contains("axes")) axes(p["axes"], w + ".axes");
  }

  void axes(const Json& a, const std::string& w) {
    if (!a.is_array() || a.size() != 3) {
      add(w, "expected 3 arrays of 3 numbers");
      return;
    }
    Eigen::Matrix3d m;
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d row;
      ok = vec3(a[i], w + "[" + std::to_string(i) + "]", &row) && ok;
      if (ok) m.row(i) = row.transpose();
    }
    if (!ok) return;
    const double err = (m * m.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (err > 1e-6) add(w, "not orthonormal (|A A^T - I| = " + std::to_string(err) + ")");
  }

  static std::string list(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& k : v) s += (s.empty() ? "" : ", ") + k;
    return s;
  }
};

}  // namespace

std::vector<std::string> schema_problems(const nlohmann::ordered_json& j) {
  Checker c;
  if (!c.keys(j, "",
              {"source", "points_in", "points_used", "resolution", "objects", "timings_ms"})) {
    return c.problems;
  }
  if (j.contains("source") && !j["source"].is_string()) c.add("source", "expected a string");
  const bool in_ok = j.contains("points_in") && c.count(j["points_in"], "points_in");
  const bool used_ok = j.contains("points_used") && c.count(j["points_used"], "points_used");
  if (in_ok && used_ok &&
      j["points_used"].get<unsigned long long>() > j["points_in"].get<unsigned long long>()) {
    c.add("points_used", "larger than points_in");
  }
  if (j.contains("resolution")) c.number(j["resolution"], "resolution", 0.0);
  if (j.contains("objects")) {
    if (!j["objects"].is_array()) {
      c.add("objects", "expected an array");
    } else {
      for (std::size_t i = 0; i < j["objects"].size(); ++i) {
        c.object(j["objects"][i], "objects[" + std::to_string(i) + "]");
      }
    }
  }
  if (j.contains("timings_ms")) {
    const std::vector<std::string> stages = {"preprocess", "planes", "keypoints",
                                             "classify",   "solve",  "total"};
    if (c.keys(j["timings_ms"], "timings_ms", stages)) {
      for (const auto& s : stages) {
        if (j["timings_ms"].contains(s)) c.number(j["timings_ms"][s], "timings_ms." + s, 0.0);
      }
    }
  }
  return c.problems;
}

}  // namespace cloudshape::report
