#include "render/label.hpp"

#include <cmath>
#include <cstdio>
#include <string_view>
#include <utility>

namespace cloudshape::render {
namespace {

// Short names keep a label inside its panel; a dimension not listed keeps its own name.
constexpr std::pair<std::string_view, std::string_view> kShortNames[] = {
    {"length", "l"}, {"width", "w"}, {"height", "h"}, {"radius", "r"}, {"top_radius", "r top"}};

std::string short_name(const std::string& name) {
  for (const auto& [full, brief] : kShortNames)
    if (name == full) return std::string(brief);
  return name;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string shape_text(const std::string& shape) {
  std::string out = shape;
  for (char& c : out)
    if (c == '_') c = ' ';
  return out;
}

}  // namespace

std::string object_tag(const pipeline::ObjectResult& object, std::size_t number) {
  return std::to_string(number) + " " + shape_text(object.shape);
}

std::string object_label(const pipeline::ObjectResult& object, std::size_t number) {
  std::string text = object_tag(object, number);
  for (const auto& [name, value] : object.dimensions)
    text += "  " + short_name(name) + " " + number_text(value);
  if (object.shape == "unknown") {
    if (!object.reason.empty()) text += "  (" + object.reason + ")";
    return text;
  }
  text += object.partial ? "  partial " : "  ";
  text += std::to_string(static_cast<int>(std::lround(100.0 * object.confidence))) + "%";
  return text;
}

}  // namespace cloudshape::render
