// Writes the ingest fuzz seeds (tests/fuzz/corpus/ingest/*.cdr) from the generated RawCloud type,
// so they follow the IDL: after a change to RawCloud run `fuzz_ingest_seeds tests/fuzz/corpus/ingest`.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cloudshapePubSubTypes.h"
#include "dds/convert.hpp"
#include "seed_file.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace {
namespace cs = cloudshape;

std::vector<double> box_xyz(std::size_t n) {
  std::mt19937_64 rng(7);
  return cs::dds::to_xyz(
      cs::synth::sample_solid_surface(cs::synth::random_solid(cs::synth::ShapeKind::box, rng, 4.0), n, rng));
}

// `n` box points at every other pixel of a 20 x 16 image (a depth frame with holes).
cs::msg::RawCloud organized(std::size_t n) {
  cs::msg::RawCloud m;
  m.xyz(box_xyz(n));
  m.width(20);
  m.height(16);
  for (std::uint32_t i = 0; i < n; ++i) m.pixel().push_back(2 * i);
  return m;
}

struct Seed {
  std::string name;
  std::function<void(cs::msg::RawCloud&)> make;
};

const std::vector<Seed>& seeds() {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  static const std::vector<Seed> all = {
      {"box_150_points", [](cs::msg::RawCloud& m) { m.xyz(box_xyz(150)); }},
      {"box_with_nan_inf",
       [=](cs::msg::RawCloud& m) {
         m.xyz(box_xyz(150));
         m.xyz()[0] = nan;
         m.xyz()[7] = inf;
         m.xyz()[11] = -inf;
       }},
      {"three_points", [](cs::msg::RawCloud& m) { m.xyz({0, 0, 0, 1, 0, 0, 0, 1, 0}); }},
      {"repeated_point",
       [](cs::msg::RawCloud& m) {
         for (int i = 0; i < 40; ++i) m.xyz().insert(m.xyz().end(), {1.5, 2.5, 3.5});
       }},
      {"collinear",
       [](cs::msg::RawCloud& m) {
         for (int i = 0; i < 60; ++i) m.xyz().insert(m.xyz().end(), {0.1 * i, 0.2 * i, -0.05 * i});
       }},
      {"ten_values", [](cs::msg::RawCloud& m) { m.xyz({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}); }},
      {"empty", [](cs::msg::RawCloud&) {}},
      {"all_nan", [=](cs::msg::RawCloud& m) { m.xyz(std::vector<double>(30, nan)); }},
      {"huge_coordinates",
       [](cs::msg::RawCloud& m) { m.xyz({1e300, -1e300, 1e-300, -1e308, 1e308, 0, 4.9e-324, 1, 2, 1e200, 1e200, 1e200}); }},
      {"object_count_zero", [](cs::msg::RawCloud& m) { m.xyz(box_xyz(50)); }},
      {"marked_failed",
       [](cs::msg::RawCloud& m) {
         m.header().error(true);
         m.header().error_stage("stage");
         m.header().error_text("upstream failure");
       }},
      {"organized_frame", [](cs::msg::RawCloud& m) { m = organized(150); }},
      {"organized_with_nan",
       [=](cs::msg::RawCloud& m) {
         m = organized(150);
         m.xyz()[3] = nan;
       }},
      {"organized_pixel_count_mismatch",
       [](cs::msg::RawCloud& m) {
         m = organized(150);
         m.pixel().pop_back();
       }},
      {"organized_pixel_outside_grid",
       [](cs::msg::RawCloud& m) {
         m = organized(150);
         m.pixel().back() = 320;
       }},
      {"organized_pixels_not_increasing",
       [](cs::msg::RawCloud& m) {
         m = organized(150);
         m.pixel()[9] = m.pixel()[8];
       }},
      {"organized_width_zero",
       [](cs::msg::RawCloud& m) {
         m = organized(150);
         m.width(0);
       }},
      {"organized_grid_overflow",
       [](cs::msg::RawCloud& m) {
         m = organized(150);
         m.width(UINT32_MAX);
         m.height(UINT32_MAX);
       }},
      {"pixels_without_height",
       [](cs::msg::RawCloud& m) {
         m = organized(150);
         m.height(1);
       }},
  };
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_ingest_seeds DIR   (writes DIR/<seed>.cdr)\n");
    return 2;
  }
  std::uint64_t id = 1;
  for (const Seed& seed : seeds()) {
    cs::msg::RawCloud m;
    seed.make(m);
    if (seed.name != "object_count_zero") m.header().object_count(1);
    m.header().cloud_id(id++);
    m.header().source(seed.name);
    if (!cs::fuzz::write_seed<cs::msg::RawCloudPubSubType>(argv[1], seed.name, m, "fuzz_ingest_seeds")) return 1;
  }
  return 0;
}
