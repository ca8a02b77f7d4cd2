// Hostile input: every truncation and many seeded random corruptions of valid files must end in
// a result or a ReadError, nothing else. Built with CLOUDSHAPE_SANITIZE this also checks memory safety.
#include <random>

#include "io/cloud_writers.hpp"
#include "io/mesh_reader.hpp"
#include "io/pcd_reader.hpp"
#include "io/ply_reader.hpp"
#include "io/xyz_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

using Reader = std::function<void(const std::string&, const ReadLimits&)>;

struct Seed {
  const char* name;
  std::string bytes;
  Reader read;
};

std::vector<Seed> seeds() {
  const PointList points = test::sample_points(40);
  const Reader pcd = [](const std::string& d, const ReadLimits& l) { read_pcd_buffer(d, "f.pcd", l); };
  const Reader ply = [](const std::string& d, const ReadLimits& l) { read_ply_buffer(d, "f.ply", l); };
  const Reader xyz = [](const std::string& d, const ReadLimits& l) { read_xyz_buffer(d, "f.xyz", l); };
  const Reader ply_mesh = [](const std::string& d, const ReadLimits& l) { read_ply_mesh_buffer(d, "f.ply", l); };
  const Reader obj_mesh = [](const std::string& d, const ReadLimits& l) { read_obj_mesh_buffer(d, "f.obj", l); };
  const std::string mesh_header =
      "ply\nformat %s 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  std::string ascii_mesh = mesh_header;
  ascii_mesh.replace(ascii_mesh.find("%s"), 2, "ascii");
  ascii_mesh += "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n4 0 1 2 3\n";
  std::string binary_mesh = mesh_header;
  binary_mesh.replace(binary_mesh.find("%s"), 2, "binary_little_endian");
  for (int i = 0; i < 12; ++i) test::append_le<float>(binary_mesh, static_cast<float>(i % 3));
  for (const auto& face : {std::vector<int>{0, 1, 2}, std::vector<int>{0, 1, 2, 3}}) {
    test::append_le<std::uint8_t>(binary_mesh, static_cast<std::uint8_t>(face.size()));
    for (int i : face) test::append_le<std::int32_t>(binary_mesh, i);
  }
  return {
      {"pcd-ascii", encode_pcd(points, PcdEncoding::ascii), pcd},
      {"pcd-binary", encode_pcd(points, PcdEncoding::binary), pcd},
      {"pcd-compressed", encode_pcd(points, PcdEncoding::binary_compressed), pcd},
      {"pcd-compressed-f8", encode_pcd(points, PcdEncoding::binary_compressed, true), pcd},
      {"ply-ascii", encode_ply(points, false), ply},
      {"ply-binary", encode_ply(points, true), ply},
      {"xyz", encode_xyz(points), xyz},
      {"ply-mesh-ascii", ascii_mesh, ply_mesh},
      {"ply-mesh-binary", binary_mesh, ply_mesh},
      {"obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 2 3 4\nf -1 -2 -3\n", obj_mesh},
  };
}

void expect_result_or_read_error(const Seed& seed, const std::string& bytes, const std::string& what) {
  ReadLimits limits;
  limits.max_points = 100000;
  limits.max_bytes = 1 << 20;
  try {
    seed.read(bytes, limits);
  } catch (const ReadError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << seed.name << " " << what << ": unexpected " << e.what();
  }
}

TEST(IoRobustness, EveryTruncation) {
  for (const Seed& seed : seeds()) {
    for (std::size_t n = 0; n < seed.bytes.size(); ++n) {
      expect_result_or_read_error(seed, seed.bytes.substr(0, n), "truncated to " + std::to_string(n));
    }
  }
}

TEST(IoRobustness, SeededRandomCorruption) {
  static constexpr char kInteresting[] = {'\0', '\n', ' ', '-', '9', '0', '#', '\xff', '\x7f', '\x80', 'e', '.'};
  std::mt19937 rng(20240611);
  for (const Seed& seed : seeds()) {
    for (int round = 0; round < 1500; ++round) {
      std::string bytes = seed.bytes;
      const int edits = 1 + static_cast<int>(rng() % 4);
      for (int e = 0; e < edits; ++e) {
        const std::size_t at = rng() % bytes.size();
        switch (rng() % 4) {
          case 0: bytes[at] = static_cast<char>(rng()); break;
          case 1: bytes[at] = kInteresting[rng() % sizeof kInteresting]; break;
          case 2: bytes.erase(at, 1 + rng() % 8); break;
          default: bytes.insert(at, 1, kInteresting[rng() % sizeof kInteresting]); break;
        }
        if (bytes.empty()) bytes = "x";
      }
      expect_result_or_read_error(seed, bytes, "round " + std::to_string(round));
    }
  }
}

// Header numbers replaced by extreme values: the readers must refuse them, not allocate them.
TEST(IoRobustness, ExtremeHeaderNumbers) {
  for (const char* value : {"0", "1", "4294967295", "4294967296", "18446744073709551615", "99999999999999999999"}) {
    for (const Seed& seed : seeds()) {
      for (const char* key : {"POINTS ", "WIDTH ", "HEIGHT ", "COUNT 1 ", "element vertex ", "element face "}) {
        std::string bytes = seed.bytes;
        const auto at = bytes.find(key);
        if (at == std::string::npos) continue;
        const auto start = at + std::string(key).size();
        bytes.replace(start, bytes.find_first_of(" \n", start) - start, value);
        expect_result_or_read_error(seed, bytes, std::string(key) + value);
      }
    }
  }
}

}  // namespace
}  // namespace cloudshape::io
