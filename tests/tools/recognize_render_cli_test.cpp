// cloudshape-recognize --render DIR as a user runs it: one PNG per recognised file, named after
// it, and one clear stderr line (exit status 2) for a bad folder or a picture that cannot be written.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "process.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape {
namespace {

namespace fs = std::filesystem;
using testing::lines_of;
using testing::ProcessResult;
using testing::run_process;

const std::string kBin = CLOUDSHAPE_RECOGNIZE_BIN;

void write_xyz(const fs::path& path, synth::ShapeKind kind, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const synth::SolidSpec spec = synth::random_solid(kind, rng, 40.0);
  std::ofstream f(path);
  f.precision(10);
  for (const auto& p : synth::sample_solid_surface(spec, 5000, rng)) f << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
}

struct PngSize {
  std::uint32_t width = 0, height = 0;
};

// The width and height from a PNG's IHDR chunk; zero when the file is no PNG.
PngSize png_size(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  unsigned char head[24] = {};
  if (!f.read(reinterpret_cast<char*>(head), sizeof head)) return {};
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!std::equal(signature, signature + 8, head) || std::string(head + 12, head + 16) != "IHDR") return {};
  const auto be32 = [&](int at) {
    return std::uint32_t{head[at]} << 24 | std::uint32_t{head[at + 1]} << 16 | std::uint32_t{head[at + 2]} << 8 |
           head[at + 3];
  };
  return {be32(16), be32(20)};
}

class RecognizeRenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "cloudshape-render-cli-XXXXXX").string();
    ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
    fs::create_directories(dir_ / "a");
    fs::create_directories(dir_ / "b");
    write_xyz(dir_ / "a" / "box.xyz", synth::ShapeKind::box, 1);
    write_xyz(dir_ / "b" / "box.xyz", synth::ShapeKind::box, 2);
    write_xyz(dir_ / "a" / "sphere.xyz", synth::ShapeKind::sphere, 3);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path dir_;
};

TEST_F(RecognizeRenderCli, WritesOnePictureOfTheRightSizePerFile) {
  const fs::path out = dir_ / "pictures" / "nested";  // made when missing
  const ProcessResult r = run_process({kBin, "--render", out.string(), (dir_ / "a" / "box.xyz").string(),
                                       (dir_ / "a" / "sphere.xyz").string(), (dir_ / "b" / "box.xyz").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines_of(r.out).size(), 3u);
  // Two inputs named box.xyz: the second picture takes the next free name.
  for (const std::string name : {"box.png", "sphere.png", "box-2.png"}) {
    const PngSize size = png_size(out / name);
    EXPECT_EQ(size.width, 1200u) << name;
    EXPECT_EQ(size.height, 800u) << name;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator{}), 3);
}

TEST_F(RecognizeRenderCli, CloudsWithNoSolidStillGetAPicture) {
  const fs::path one = dir_ / "one_point.xyz", same = dir_ / "same_point.xyz";
  std::ofstream(one) << "1 2 3\n";
  std::ofstream f(same);
  for (int i = 0; i < 500; ++i) f << "4 5 6\n";
  f.close();
  const fs::path out = dir_ / "pictures";
  const ProcessResult r = run_process({kBin, "--render", out.string(), one.string(), same.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(png_size(out / "one_point.png").width, 1200u);
  EXPECT_EQ(png_size(out / "same_point.png").height, 800u);
}

TEST_F(RecognizeRenderCli, AFolderThatIsAFileIsOneClearErrorBeforeAnyInput) {
  const fs::path file = dir_ / "a" / "box.xyz";
  const ProcessResult r = run_process({kBin, "--render", file.string(), file.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  const auto err = lines_of(r.err);
  ASSERT_EQ(err.size(), 1u) << r.err;
  EXPECT_EQ(err[0], "cloudshape-recognize: --render " + file.string() + ": not a folder");

  const fs::path under_file = file / "pictures";
  const ProcessResult under = run_process({kBin, "--render", under_file.string(), file.string()});
  EXPECT_EQ(under.exit_code, 2);
  ASSERT_EQ(lines_of(under.err).size(), 1u) << under.err;
  EXPECT_EQ(lines_of(under.err)[0].rfind("cloudshape-recognize: --render " + under_file.string() + ": cannot create", 0), 0u)
      << under.err;

  const ProcessResult empty = run_process({kBin, "--render", "", file.string()});
  EXPECT_EQ(empty.exit_code, 2);
  EXPECT_NE(empty.err.find("--render needs a folder name"), std::string::npos) << empty.err;
}

TEST_F(RecognizeRenderCli, APictureThatCannotBeWrittenNamesItsFileAndTheOthersGoOn) {
  const fs::path out = dir_ / "pictures";
  fs::create_directories(out / "box.png");  // a folder where box's picture should go
  const std::string box = (dir_ / "a" / "box.xyz").string();
  const ProcessResult r = run_process({kBin, "--render", out.string(), box, (dir_ / "a" / "sphere.xyz").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines_of(r.out).size(), 2u) << "the results are still printed";
  const auto err = lines_of(r.err);
  ASSERT_EQ(err.size(), 1u) << r.err;
  EXPECT_EQ(err[0].rfind("cloudshape-recognize: " + box + ": no picture: " + (out / "box.png").string() + ": ", 0), 0u)
      << err[0];
  EXPECT_EQ(png_size(out / "sphere.png").width, 1200u);
}

}  // namespace
}  // namespace cloudshape
