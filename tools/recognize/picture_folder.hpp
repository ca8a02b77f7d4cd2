// Where --render puts its pictures: a folder checked once before any input is read, and one
// PNG name per recognised cloud, unique within the run.
#pragma once

#include <filesystem>
#include <set>
#include <string>

namespace cloudshape::tools {

class PictureFolder {
 public:
  // Creates the folder when it is missing. Throws std::runtime_error naming it when it is not
  // a folder or cannot be made or written to.
  explicit PictureFolder(std::filesystem::path dir);

  // DIR/<render::picture_stem(source)>.png, with -2, -3, ... appended when an earlier cloud of
  // this run took that name.
  std::filesystem::path path_for(const std::string& source);

 private:
  std::filesystem::path dir_;
  std::set<std::string> taken_;
};

}  // namespace cloudshape::tools
