// cloudshape-bench --accuracy --save-clouds DIR: the directory is made when missing, every
// scored cloud lands in it, and a path that cannot be a directory is refused before any work.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "process.hpp"

namespace cloudshape {
namespace {

namespace fs = std::filesystem;
using testing::run_process;

const std::string kBin = CLOUDSHAPE_BENCH_BIN;

class BenchSaveClouds : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "cloudshape-bench-save-XXXXXX").string();
    ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
};

TEST_F(BenchSaveClouds, AMissingDirectoryIsMadeAndHoldsEveryCloud) {
  const fs::path out = dir_ / "not" / "yet";
  const auto run = run_process({kBin, "--accuracy", "--count", "1", "--max-points", "2000",
                                "--conditions", "clean", "--save-clouds", out.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // One cloud per shape of the clean condition (six solids), none lost.
  std::size_t written = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    EXPECT_EQ(entry.path().extension(), ".pcd") << entry.path();
    EXPECT_GT(fs::file_size(entry.path()), 0u) << entry.path();
    ++written;
  }
  EXPECT_EQ(written, 6u);
}

TEST_F(BenchSaveClouds, AFileInTheWayIsAnErrorNamingThePath) {
  const fs::path file = dir_ / "a_file";
  std::ofstream(file) << "not a directory\n";
  const auto run = run_process({kBin, "--accuracy", "--count", "1", "--conditions", "clean",
                                "--save-clouds", file.string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--save-clouds"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(file.string()), std::string::npos) << run.err;
  EXPECT_EQ(run.out, "") << "nothing measured before the refusal";
}

}  // namespace
}  // namespace cloudshape
