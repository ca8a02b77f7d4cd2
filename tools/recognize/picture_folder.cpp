#include "picture_folder.hpp"

#include <unistd.h>

#include <stdexcept>
#include <system_error>

#include "render/picture_name.hpp"

namespace cloudshape::tools {

PictureFolder::PictureFolder(std::filesystem::path dir) : dir_(std::move(dir)) {
  const std::string name = "--render " + dir_.string();
  if (dir_.empty()) throw std::runtime_error("--render needs a folder name");
  std::error_code ec;
  const auto status = std::filesystem::status(dir_, ec);
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_directory(status)) throw std::runtime_error(name + ": not a folder");
  } else if (!std::filesystem::create_directories(dir_, ec) || ec) {
    throw std::runtime_error(name + ": cannot create the folder: " +
                             (ec ? ec.message() : std::string("unknown error")));
  }
  if (::access(dir_.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(name + ": the folder is not writable");
}

std::filesystem::path PictureFolder::path_for(const std::string& source) {
  const std::string stem = render::picture_stem(source);
  std::string name = stem;
  for (int n = 2; taken_.count(name) > 0; ++n) name = stem + "-" + std::to_string(n);
  taken_.insert(name);
  return dir_ / (name + ".png");
}

}  // namespace cloudshape::tools
