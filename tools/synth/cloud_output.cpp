#include "cloud_output.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace cloudshape::synth_tool {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

void check_output_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".pcd" && ext != ".ply" && ext != ".xyz" && ext != ".txt")
    throw std::invalid_argument(path + ": unsupported output extension '" + ext +
                                "' (use .pcd, .ply, .xyz or .txt)");
}

void write_cloud(const std::string& path, const PointList& points, io::PcdEncoding pcd_encoding) {
  check_output_path(path);
  const std::string ext = lower_extension(path);
  if (ext == ".pcd")
    io::write_pcd(path, points, pcd_encoding);
  else if (ext == ".ply")
    io::write_ply(path, points, true);
  else
    io::write_xyz(path, points);
}

std::string ground_truth_path(const std::string& cloud_path) {
  return std::filesystem::path(cloud_path).replace_extension(".json").string();
}

void write_json(const std::string& path, const nlohmann::json& document) {
  std::ofstream out(path);
  out << document.dump() << '\n';
  if (!out) throw std::runtime_error(path + ": cannot write file");
}

}  // namespace cloudshape::synth_tool
