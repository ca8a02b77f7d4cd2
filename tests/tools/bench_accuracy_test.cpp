// The accuracy gate: cloudshape-bench --accuracy in a fast form (fixed seed, 5 clouds per
// shape, at most 12 000 points), one test per condition, held to floors under the README.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "accuracy_suites.hpp"
#include "process.hpp"
#include "shared_data.hpp"

namespace cloudshape {
namespace {

using Json = nlohmann::json;
using testing::run_process;

const std::string kBin = CLOUDSHAPE_BENCH_BIN;

// The fast form. 12 000 points is the preprocessing budget (preprocess.max_points): a cloud
// drawn larger is gridded down to about that anyway, so capping it there keeps the answers
// close to the full run's at a fraction of the sampling cost.
const std::vector<std::string> kFastForm = {kBin,           "--accuracy", "--count", "5",
                                            "--max-points", "12000",      "--seed",  "42",
                                            "--json"};

// What a condition must reach on its "all" row. Floors sit a few points under what this fast
// form measured (see the figures beside each) and under the README's --accuracy table; the
// error ceilings are about twice the measured ones, so a fit gone wrong fails and noise in
// the last digit does not. Error figures are fractions (0.01 = 1%).
struct Gate {
  std::string condition;
  std::size_t clouds;       // exactly this many (6 shapes x 5; real: every SOURCES.md sample)
  double min_right_pct;     // README figure, measured fast-form figure in the comment
  double max_dim_median;
  double max_dim_p90;
  double max_centre_median;  // < 0: not scored (real samples have no pose truth)
  double max_axis_deg_median;
  int max_false_objects;
  int max_missed_objects;
};

void PrintTo(const Gate& g, std::ostream* os) { *os << g.condition; }

const std::vector<Gate>& gates() {
  static const std::vector<Gate> all = {
      // condition     clouds right%  dim med  dim p90  centre   axis  false missed
      {"clean",        30,    97.0,   0.0010,  0.0030,  0.0010,  0.10,  0,   0},
      {"noise",        30,    97.0,   0.0020,  0.0060,  0.0010,  0.20,  0,   0},
      {"outliers",     30,    95.0,   0.0100,  0.0400,  0.0050,  0.50,  1,   1},
      {"density",      30,    97.0,   0.0010,  0.0030,  0.0010,  0.10,  2,   0},
      {"single_view",  30,    85.0,   0.0060,  0.0150,  0.0050,  0.10,  1,   1},
      {"table_view",   30,    85.0,   0.0060,  0.0200,  0.0080,  0.10,  1,   1},
      {"multi",        30,    92.0,   0.0040,  0.0250,  0.0010,  0.20,  2,   2},
      {"real",         15,    97.0,   0.0050,  0.0250,  -1.0,    -1.0,  0,   0},
  };
  return all;
}

double number(const Json& j, const char* what) {
  if (j.is_null()) {
    ADD_FAILURE() << what << " is null: no right-shape object to measure it on";
    return 1e9;
  }
  return j.get<double>();
}

class AccuracyGate : public ::testing::TestWithParam<Gate> {};

TEST_P(AccuracyGate, ConditionMeetsItsFloor) {
  const Gate& g = GetParam();
  if (g.condition == "real") CLOUDSHAPE_REQUIRE_SHARED_DATA(testing::shared_data_path("real"));
  std::vector<std::string> argv = kFastForm;
  argv.insert(argv.end(), {"--conditions", g.condition});
  const auto run = run_process(argv);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json out = Json::parse(run.out);
  ASSERT_EQ(out.at("conditions").size(), 1u);
  const Json& c = out.at("conditions")[0];
  ASSERT_EQ(c.at("name"), g.condition);
  // A condition that produced no cloud measured nothing: that is a failure, never a pass.
  ASSERT_GT(c.at("clouds").get<std::size_t>(), 0u) << run.err;
  EXPECT_EQ(c.at("clouds").get<std::size_t>(), g.clouds) << run.err;

  const Json& all = c.at("rows").back();
  ASSERT_EQ(all.at("shape"), "all");
  const std::string figures = "measured: " + all.dump();
  EXPECT_GE(all.at("recognized_pct").get<double>(), g.min_right_pct) << figures;
  const Json& dim = all.at("dimension_error");
  EXPECT_LE(number(dim.at("median"), "dimension error median"), g.max_dim_median) << figures;
  EXPECT_LE(number(dim.at("p90"), "dimension error p90"), g.max_dim_p90) << figures;
  if (g.max_centre_median >= 0) {
    EXPECT_LE(number(all.at("centre_error_median"), "centre error"), g.max_centre_median)
        << figures;
  }
  if (g.max_axis_deg_median >= 0) {
    EXPECT_LE(number(all.at("axis_error_deg_median"), "axis error"), g.max_axis_deg_median)
        << figures;
  }
  EXPECT_LE(all.at("false_objects").get<int>(), g.max_false_objects) << figures;
  EXPECT_LE(all.at("missed_objects").get<int>(), g.max_missed_objects) << figures;
  // Every single-object synthetic cloud holds one solid.
  if (g.condition != "multi" && g.condition != "real") {
    EXPECT_EQ(all.at("objects").get<std::size_t>(), g.clouds);
  }
}

INSTANTIATE_TEST_SUITE_P(FastForm, AccuracyGate, ::testing::ValuesIn(gates()),
                         [](const auto& info) { return info.param.condition; });

// A condition added to the bench without a gate here would go unguarded.
TEST(BenchAccuracy, GatesCoverEveryConditionInTheReportsOrder) {
  std::vector<std::string> gated;
  for (const Gate& g : gates()) gated.push_back(g.condition);
  EXPECT_EQ(gated, bench::accuracy_conditions());
}

TEST(BenchAccuracy, UnknownConditionIsAnError) {
  const auto run = run_process({kBin, "--accuracy", "--count", "1", "--conditions", "clean,foggy"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("foggy"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace cloudshape
