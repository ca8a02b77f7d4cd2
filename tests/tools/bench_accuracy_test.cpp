// cloudshape-bench --accuracy at its smallest (2 clouds per shape): it must finish, print
// parseable JSON with every condition and an "all" row, and reject an unknown condition.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "process.hpp"

namespace cloudshape {
namespace {

using Json = nlohmann::json;
using testing::run_process;

const std::string kBin = CLOUDSHAPE_BENCH_BIN;

TEST(BenchAccuracy, SmokeRunPrintsEveryConditionAsJson) {
  const auto run = run_process({kBin, "--accuracy", "--count", "2", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json out = Json::parse(run.out);
  EXPECT_EQ(out.at("settings").at("count"), 2);
  std::vector<std::string> names;
  for (const auto& c : out.at("conditions")) {
    names.push_back(c.at("name"));
    if (c.at("clouds") == 0) continue;  // real: the shared data is not checked out
    const Json& all = c.at("rows").back();
    EXPECT_EQ(all.at("shape"), "all");
    // Single-object synthetic conditions hold 2 clouds x 6 shapes, one solid each.
    if (c.at("name") != "multi" && c.at("name") != "real") {
      EXPECT_EQ(all.at("objects"), 12);
    }
    // Loose on purpose: this checks the scoring, not the recognizer's quality.
    if (c.at("name") == "clean") {
      EXPECT_GE(all.at("recognized_pct").get<double>(), 50.0);
    }
  }
  EXPECT_EQ(names, (std::vector<std::string>{"clean", "noise", "outliers", "density",
                                             "single_view", "table_view", "multi", "real"}));
}

TEST(BenchAccuracy, UnknownConditionIsAnError) {
  const auto run = run_process({kBin, "--accuracy", "--count", "1", "--conditions", "clean,foggy"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("foggy"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace cloudshape
