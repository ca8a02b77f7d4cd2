// Writes the MCAP fuzz seeds (tests/fuzz/corpus/mcap/*.mcap): small rosbag2-like recordings of
// box clouds as PointCloud2, one per chunk compression, organized or not, float32 or float64.
//   fuzz_mcap_seeds tests/fuzz/corpus/mcap
#include <cstdio>
#include <random>
#include <string>

#include "io/mcap_writer.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/ros2_schemas.hpp"
#include "io/pointcloud2_encode.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace {
namespace cs = cloudshape;

struct Seed {
  const char* name;
  cs::io::McapCompression compression;
  bool chunked;
  bool organized;
  bool float64;
  std::size_t chunk_size;  // 1: a chunk per message, so a read from message 1 on skips one
  bool indexed;            // message indexes and chunk indexes (what a seek uses)
  std::uint64_t messages;
};

void write_seed(const std::string& dir, const Seed& seed) {
  std::mt19937_64 rng(11);
  const cs::PointList points =
      cs::synth::sample_solid_surface(cs::synth::random_solid(cs::synth::ShapeKind::box, rng, 4.0), 40, rng);
  cs::GridLayout grid;
  if (seed.organized) {
    grid.width = 10;
    grid.height = 6;
    for (std::uint32_t i = 0; i < 40; ++i) grid.pixel.push_back(i + i / 2);
  }
  cs::io::McapWriterOptions options;
  options.compression = seed.compression;
  options.chunked = seed.chunked;
  options.chunk_size = seed.chunk_size;
  options.indexed = seed.indexed;
  cs::io::McapWriter writer(dir + "/" + seed.name + ".mcap", options);
  const auto schema = writer.add_schema(cs::io::kPointCloud2SchemaName, "ros2msg",
                                        cs::io::ros2_schema_text(cs::io::kPointCloud2SchemaName));
  const auto channel = writer.add_channel(schema, "/camera/depth/points", "cdr");
  const cs::io::PointCloud2Layout layout = seed.float64 ? cs::io::float64_layout() : cs::io::PointCloud2Layout{};
  for (std::uint64_t i = 0; i < seed.messages; ++i) {
    const cs::io::PointCloud2 msg = cs::io::encode_pointcloud2(points, grid, layout, {{1, 0}, "camera"});
    writer.write(channel, 1'000'000'000 + i * 33'000'000, 1'000'000'000 + i * 33'000'000,
                 cs::io::pointcloud2_to_cdr(msg));
  }
  writer.close();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_mcap_seeds DIR\n");
    return 2;
  }
  using C = cs::io::McapCompression;
  for (const Seed& seed : {Seed{"zstd_chunks_float32", C::zstd, true, false, false, 1024, true, 2},
                           Seed{"lz4_chunks_organized", C::lz4, true, true, false, 1024, true, 2},
                           Seed{"uncompressed_chunks_float64", C::none, true, false, true, 1024, true, 2},
                           Seed{"unchunked_organized_float64", C::none, false, true, true, 1024, true, 2},
                           Seed{"seek_chunk_per_message", C::none, true, false, false, 1, true, 4},
                           Seed{"seek_lz4_chunk_per_message", C::lz4, true, true, false, 1, true, 3},
                           Seed{"seek_chunks_without_indexes", C::none, true, false, false, 1, false, 3}}) {
    write_seed(argv[1], seed);
  }
  return 0;
}
