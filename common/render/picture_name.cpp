#include "render/picture_name.hpp"

#include <algorithm>
#include <cctype>

namespace cloudshape::render {

std::string picture_stem(const std::string& source) {
  const std::size_t slash = source.find_last_of("/\\");
  std::string name = slash == std::string::npos ? source : source.substr(slash + 1);
  const std::size_t dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0 && dot + 1 < name.size() &&
      std::all_of(name.begin() + static_cast<std::ptrdiff_t>(dot) + 1, name.end(),
                  [](unsigned char c) { return std::isalnum(c) != 0; }))
    name.erase(dot);
  for (char& c : name) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (!(std::isalnum(u) || c == '.' || c == '-' || c == '_')) c = '_';
  }
  if (name.empty() || name == "." || name == "..") return "cloud";
  return name;
}

}  // namespace cloudshape::render
