#include "synth/ground_truth.hpp"

#include <array>

namespace cloudshape::synth {

namespace {

struct KindInfo {
  ShapeKind kind;
  const char* name;
};

constexpr std::array<KindInfo, 6> kKinds{{
    {ShapeKind::box, "box"},
    {ShapeKind::tetrahedron, "tetrahedron"},
    {ShapeKind::pentagonal_prism, "pentagonal_prism"},
    {ShapeKind::cone, "cone"},
    {ShapeKind::cylinder, "cylinder"},
    {ShapeKind::sphere, "sphere"},
}};

}  // namespace

const std::vector<ShapeKind>& all_shape_kinds() {
  static const std::vector<ShapeKind> kinds = [] {
    std::vector<ShapeKind> v;
    for (const auto& k : kKinds) v.push_back(k.kind);
    return v;
  }();
  return kinds;
}

std::string to_string(ShapeKind kind) {
  for (const auto& k : kKinds)
    if (k.kind == kind) return k.name;
  return "unknown";
}

std::optional<ShapeKind> shape_kind_from_string(std::string_view name) {
  for (const auto& k : kKinds)
    if (name == k.name) return k.kind;
  return std::nullopt;
}

const std::vector<std::string>& dimension_names(ShapeKind kind) {
  static const std::vector<std::string> box{"length", "width", "height"};
  static const std::vector<std::string> tetra{"edge"};
  static const std::vector<std::string> prism{"side", "height"};
  static const std::vector<std::string> round{"radius", "height"};
  static const std::vector<std::string> sphere{"radius"};
  switch (kind) {
    case ShapeKind::box:
      return box;
    case ShapeKind::tetrahedron:
      return tetra;
    case ShapeKind::pentagonal_prism:
      return prism;
    case ShapeKind::cone:
    case ShapeKind::cylinder:
      return round;
    case ShapeKind::sphere:
      return sphere;
  }
  return sphere;
}

}  // namespace cloudshape::synth
