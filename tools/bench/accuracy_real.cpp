// Real samples for the accuracy benchmark: mesh files sampled like tools/demo.sh does.
// Truth values are copied from shared/data/real/SOURCES.md (face-to-face, mm).
#include "accuracy_real.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "io/mesh_reader.hpp"
#include "synth/mesh_sampling.hpp"

namespace cloudshape::bench {

namespace {

struct RealSample {
  const char* file;  // under real/
  const char* shape;
  std::vector<std::pair<std::string, double>> dimensions_mm;
  double file_units_per_mm;  // YCB files are in metres, ravens in mm
};

const std::vector<RealSample>& real_table() {
  constexpr double ycb = 0.001;
  using D = std::vector<std::pair<std::string, double>>;
  const auto box = [](double l, double w, double h) {
    return D{{"length", l}, {"width", w}, {"height", h}};
  };
  const auto cylinder = [](double r, double h) { return D{{"radius", r}, {"height", h}}; };
  static const std::vector<RealSample> table = {
      {"ycb/003_cracker_box_google16k.obj", "box", box(210.6, 159.4, 69.5), ycb},
      {"ycb/004_sugar_box_google16k.obj", "box", box(173.4, 89.7, 43.6), ycb},
      {"ycb/009_gelatin_box_google16k.obj", "box", box(87.1, 71.2, 28.7), ycb},
      {"ycb/061_foam_brick_google16k.obj", "box", box(74.9, 50.6, 49.7), ycb},
      {"ycb/036_wood_block_google16k.obj", "box", box(204.5, 88.4, 87.1), ycb},
      {"ycb/077_rubiks_cube_google16k.obj", "box", box(56.9, 56.8, 56.5), ycb},
      {"ycb/070-b_colored_wood_blocks_google16k.obj", "box", box(25.4, 25.4, 25.3), ycb},
      {"ycb/002_master_chef_can_google16k.obj", "cylinder", cylinder(49.85, 140.2), ycb},
      {"ycb/005_tomato_soup_can_google16k.obj", "cylinder", cylinder(32.95, 101.9), ycb},
      {"ycb/007_tuna_fish_can_google16k.obj", "cylinder", cylinder(42.0, 33.5), ycb},
      {"ycb/055_baseball_google16k.obj", "sphere", D{{"radius", 36.55}}, ycb},
      {"ycb/056_tennis_ball_google16k_nontextured.ply", "sphere", D{{"radius", 33.4}}, ycb},
      {"ycb/058_golf_ball_google16k.obj", "sphere", D{{"radius", 21.25}}, ycb},
      {"ravens/kitting_03_cube.obj", "box", box(20.0, 20.0, 20.0), 1.0},
      {"ravens/kitting_07_pentagonal_prism.obj", "pentagonal_prism",
       D{{"side", 11.775}, {"height", 20.032}}, 1.0},
  };
  return table;
}

// Largest extent: the unit of the (unscored) centre error; any sane value would do.
double largest_extent(const Truth& t) {
  double size = 0.0;
  for (const auto& [name, v] : t.dimensions) {
    const bool across = name == "radius" || name == "side";  // side: pentagon ~1.7 sides wide
    size = std::max(size, across ? 2.0 * v : v);
  }
  return size;
}

std::filesystem::path real_dir(const std::string& shared_data_dir) {
  return std::filesystem::path(shared_data_dir) / "real";
}

}  // namespace

std::vector<std::size_t> present_real_samples(const std::string& shared_data_dir) {
  std::vector<std::size_t> present;
  if (shared_data_dir.empty()) return present;
  const auto& table = real_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(real_dir(shared_data_dir) / table[i].file, ec))
      present.push_back(i);
  }
  return present;
}

TestCloud make_real_cloud(std::size_t entry, const std::string& shared_data_dir) {
  const RealSample& sample = real_table().at(entry);
  const io::Mesh mesh = io::read_mesh((real_dir(shared_data_dir) / sample.file).string());
  std::mt19937_64 rng(1);
  TestCloud cloud;
  cloud.source = std::filesystem::path(sample.file).filename().string();
  cloud.points = synth::sample_mesh_surface(mesh.vertices, mesh.triangles, 20000, rng);

  Truth truth;
  truth.shape = sample.shape;
  truth.label = cloud.source;
  for (const auto& [name, mm] : sample.dimensions_mm)
    truth.dimensions.emplace_back(name, mm * sample.file_units_per_mm);
  // Pose truth is unknown: the centroid only serves to pick the result that answers.
  truth.has_pose = false;
  for (const auto& p : cloud.points) truth.center += p;
  truth.center /= static_cast<double>(cloud.points.size());
  truth.size = largest_extent(truth);
  cloud.truths.push_back(std::move(truth));
  return cloud;
}

}  // namespace cloudshape::bench
