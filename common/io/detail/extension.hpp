// The lower-cased extension of a path (".pcd"), which is how the readers pick a format.
// Lower-casing lets "SCAN.PCD" from a camera's SD card read like "scan.pcd".
#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace cloudshape::io::detail {

inline std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace cloudshape::io::detail
