// cloudshape-bench --pool: one row per block size, the pool's size as the run's blocks, and it
// runs alone (not with --scenes or --accuracy).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "process.hpp"

namespace cloudshape {
namespace {

const std::string kBin = CLOUDSHAPE_BENCH_BIN;

TEST(BenchPool, RowsGrowWithTheBlocksWorkAndRunOneBlockAThread) {
  const auto run = testing::run_process({kBin, "--pool", "--threads", "2", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json out = nlohmann::json::parse(run.out);
  EXPECT_EQ(out.at("threads"), 2);
  EXPECT_EQ(out.at("blocks"), 2);
  const nlohmann::json& rows = out.at("rows");
  ASSERT_EQ(rows.size(), 5u) << out.dump();
  // Each row has ten times the steps of the one before (four times for the last): its block
  // takes longer by far more than any timing noise.
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_GT(rows[r].at("block_us").get<double>(), 2.0 * rows[r - 1].at("block_us").get<double>())
        << out.dump();
    EXPECT_GT(rows[r].at("in_order_us").get<double>(), 0.0) << out.dump();
    EXPECT_GT(rows[r].at("pool_us").get<double>(), 0.0) << out.dump();
  }
}

TEST(BenchPool, RunsAloneNotWithTheScenesOrTheAccuracy) {
  for (const char* other : {"--accuracy", "--scenes"}) {
    std::vector<std::string> argv{kBin, "--pool", other};
    if (std::string(other) == "--scenes") argv.push_back("/tmp");
    const auto run = testing::run_process(argv);
    EXPECT_NE(run.exit_code, 0) << other;
    EXPECT_NE(run.err.find("excludes"), std::string::npos) << other << ": " << run.err;
  }
}

}  // namespace
}  // namespace cloudshape
