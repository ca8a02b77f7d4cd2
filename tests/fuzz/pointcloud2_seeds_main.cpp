// Writes the PointCloud2 fuzz seeds (tests/fuzz/corpus/pointcloud2/*.cdr) from the generated ROS 2
// type: every layout ingest takes and every bad one it refuses. `fuzz_pointcloud2_seeds DIR`.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io/pointcloud2_encode.hpp"
#include "ros2/messages.hpp"
#include "seed_file.hpp"
#include "sensor_msgsPubSubTypes.h"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace {
namespace cs = cloudshape;
using cs::io::PointCloud2;

cs::PointList box(std::size_t n) {
  std::mt19937_64 rng(7);
  return cs::synth::sample_solid_surface(cs::synth::random_solid(cs::synth::ShapeKind::box, rng, 4.0), n, rng);
}

const cs::io::RosHeader kHeader{{17, 42}, "camera"};

PointCloud2 flat(const cs::io::PointCloud2Layout& layout = {}) {
  return cs::io::encode_pointcloud2(box(150), {}, layout, kHeader);
}

// 150 box points at every other pixel of a 20 x 16 image (a depth frame with holes).
PointCloud2 organized(const cs::io::PointCloud2Layout& layout = {}) {
  cs::GridLayout grid;
  grid.width = 20;
  grid.height = 16;
  for (std::uint32_t i = 0; i < 150; ++i) grid.pixel.push_back(2 * i);
  return cs::io::encode_pointcloud2(box(150), grid, layout, kHeader);
}

// `cloud` with one thing broken by `spoil`.
PointCloud2 spoiled(PointCloud2 cloud, const std::function<void(PointCloud2&)>& spoil) {
  spoil(cloud);
  return cloud;
}

struct Seed {
  std::string name;
  std::function<PointCloud2()> make;
};

std::vector<Seed> seeds() {
  cs::io::PointCloud2Layout odd = cs::io::float64_layout();
  odd.offsets = {20, 4, 36};
  odd.rgb_offset = 0;
  odd.point_step = 47;
  odd.row_padding = 13;
  cs::io::PointCloud2Layout big;
  big.big_endian = true;
  cs::io::PointCloud2Layout big64 = cs::io::float64_layout();
  big64.big_endian = true;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {
      {"float32_rgb", [] { return flat(); }},
      {"float64", [] { return flat(cs::io::float64_layout()); }},
      {"float64_odd_offsets_padded", [=] { return flat(odd); }},
      {"float32_big_endian", [=] { return flat(big); }},
      {"organized_float32", [] { return organized(); }},
      {"organized_float64_big_endian", [=] { return organized(big64); }},
      {"nan_and_inf",
       [=] {
         cs::PointList p = box(150);
         p[3].x() = nan;
         p[9].z() = std::numeric_limits<double>::infinity();
         return cs::io::encode_pointcloud2(p, {}, {}, kHeader);
       }},
      {"extra_fields",
       [] {
         cs::io::PointCloud2Layout wide;
         wide.point_step = 32;
         PointCloud2 c = flat(wide);
         for (std::uint8_t t = 1; t <= 8; ++t) c.fields.push_back({"f" + std::to_string(t), 16u + 2u * t, t, 1});
         return c;
       }},
      {"empty", [] { return cs::io::encode_pointcloud2({}, {}, {}, kHeader); }},
      {"no_z",
       [] { return spoiled(flat(), [](PointCloud2& c) { c.fields[2].name = "depth"; }); }},
      {"offset_past_point_step",
       [] { return spoiled(flat(), [](PointCloud2& c) { c.fields[3].offset = 14; }); }},
      {"count_past_point_step",
       [] { return spoiled(flat(), [](PointCloud2& c) { c.fields[1].count = 4; }); }},
      {"data_short",
       [] { return spoiled(flat(), [](PointCloud2& c) { c.data.resize(c.data.size() - 5); }); }},
      {"height_disagrees",
       [] { return spoiled(flat(), [](PointCloud2& c) { c.height = 2; }); }},
      {"row_step_short",
       [] { return spoiled(organized(), [](PointCloud2& c) { c.row_step -= 1; }); }},
      {"int16_x",
       [] { return spoiled(flat(), [](PointCloud2& c) { c.fields[0].datatype = 3; }); }},
      {"unknown_datatype",
       [] { return spoiled(flat(), [](PointCloud2& c) { c.fields[3].datatype = 11; }); }},
  };
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_pointcloud2_seeds DIR   (writes DIR/<seed>.cdr)\n");
    return 2;
  }
  for (const Seed& seed : seeds()) {
    sensor_msgs::msg::PointCloud2 m = cs::ros2::to_msg(seed.make());
    if (!cs::fuzz::write_seed<sensor_msgs::msg::PointCloud2PubSubType>(argv[1], seed.name, m, "fuzz_pointcloud2_seeds")) {
      return 1;
    }
  }
  return 0;
}
