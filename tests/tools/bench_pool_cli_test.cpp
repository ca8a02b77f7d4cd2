// cloudshape-bench --pool: one row per block size, the pool's size as the run's blocks, and it
// runs alone (not with --scenes or --accuracy).
#include <gtest/gtest.h>

#include <cmath>
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
  // The work a row gives each block is fixed and grows from row to row; its times are whatever
  // the machine's load makes them (a benchmark's figures, not asserted against each other), but
  // every row measured something.
  EXPECT_EQ(rows[0].at("block_steps").get<std::size_t>(), 0u) << out.dump();
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_GT(rows[r].at("block_steps").get<std::size_t>(),
              rows[r - 1].at("block_steps").get<std::size_t>())
        << out.dump();
    for (const char* field : {"block_us", "in_order_us", "pool_us", "speedup"}) {
      const double value = rows[r].at(field).get<double>();
      EXPECT_TRUE(std::isfinite(value) && value > 0.0) << field << " " << out.dump();
    }
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
