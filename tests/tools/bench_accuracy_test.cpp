// The accuracy gate: cloudshape-bench --accuracy in a fast form (the README's seed and count,
// clouds capped at 12 000 points), one test per condition, held to floors under the README.
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

// The fast form: the README's solids, poses and cameras (seed 42, 30 per shape), with no
// cloud above 12 000 points, the preprocessing budget (preprocess.max_points) that larger
// clouds are gridded down to anyway. 35-50 s of one core for the eight conditions.
const std::vector<std::string> kFastForm = {
    kBin, "--accuracy", "--count", "30", "--max-points", "12000", "--seed", "42", "--json"};

// What a condition's "all" row must reach. Right-shape floors sit about 3 points under the
// lower of this fast form's figure and the README's (Robustness, measured); error ceilings
// at about twice the larger of the two, so a fit gone wrong fails while a change in the
// last digit does not; false and missed objects at most one more than either. Beside each
// row: measured on 51bace5 in this fast form / the README's figure. Errors are fractions.
struct Gate {
  std::string condition;
  std::size_t clouds;  // exactly this many: 6 shapes x 30, or every real sample of SOURCES.md
  double min_right_pct;
  double max_dim_median;       // < 0: not scored (negatives: an unknown has no dimensions)
  double max_dim_p90;
  double max_centre_median;    // < 0: not scored (the real samples have no pose truth)
  double max_axis_deg_median;  // < 0: likewise
  int max_false_objects;
  int max_missed_objects;
};

void PrintTo(const Gate& g, std::ostream* os) { *os << g.condition; }

const std::vector<Gate>& gates() {
  static const std::vector<Gate> all = {
      // right%; dimension median, p90; centre; axis deg; false, missed (fast / README)
      // clean: 100 / 100; 0.009%, 0.053% / 0.01%, 0.07%; 0.002% / 0.00%; 0.005 / 0.00; 0, 0
      {"clean", 180, 97.0, 0.0002, 0.0015, 0.0001, 0.05, 1, 1},
      // noise: 100 / 100; 0.070%, 0.206% / 0.06%, 0.20%; 0.025% / 0.02%; 0.043 / 0.04; 0, 0
      {"noise", 180, 97.0, 0.0015, 0.0045, 0.0005, 0.10, 1, 1},
      // outliers: 100 / 98.9; 0.291%, 1.115% / 0.46%, 2.15%; 0.126% / 0.17%; 0.169 / 0.19;
      // 0, 0
      {"outliers", 180, 95.5, 0.0090, 0.0430, 0.0035, 0.40, 1, 1},
      // density: 96.7 / 100 (capped, 6 of 30 prisms unknown: 5 of them boxes that enclosed their
      // slanted faces before solve.off_surface_max_share); 0.009%, 0.049% /
      // 0.01%, 0.07%; 0.004% / 0.00%; 0.009 / 0.01; false 3 / 2, missed 0
      {"density", 180, 93.5, 0.0002, 0.0015, 0.0001, 0.05, 4, 1},
      // single_view: 92.2 / 92.2 (14 unknown); 0.296%, 0.665% / 0.26%, 0.55%; 0.191% / 0.14%;
      // 0.008 / 0.01; 0, 0
      {"single_view", 180, 89.0, 0.0060, 0.0140, 0.0040, 0.05, 1, 1},
      // table_view: 92.8 / 92.8 (13 unknown); 0.292%, 0.730% / 0.27%, 0.79%; 0.335% / 0.34%;
      // 0.008 / 0.01; 0, 0
      {"table_view", 180, 89.5, 0.0060, 0.0160, 0.0070, 0.05, 1, 1},
      // multi (562 objects): 96.4 / 96.4; 0.138%, 1.047% / 0.14%, 1.04%; 0.020% / 0.02%;
      // 0.065 / 0.06; 0, 0
      {"multi", 180, 93.5, 0.0030, 0.0210, 0.0005, 0.15, 1, 1},
      // real (15 samples at 20k points, not capped): 15/15 / 15/15; 0.210%, 1.092% / 0.21%,
      // 1.09%; 0, 0
      {"real", 15, 97.0, 0.0045, 0.0220, -1.0, -1.0, 1, 1},
      // negatives (ellipsoid, torus, square pyramid, octahedron, capsule; 30 each): right =
      // unknown. 100 (fast form, shapes-3; prism-2: 77.5, box 20 octahedra, tetrahedron 4,
      // cylinder 3; capsules cylinders but for solve.off_surface_max_share). Issue 11 asks 95
      // and none named as one of the six (checked below).
      {"negatives", 150, 97.0, -1.0, -1.0, -1.0, -1.0, 1, 1},
      // new_shapes (30 frusta, 30 prisms of nine cross-section kinds, 30 irregular tetrahedra,
      // noise 0.5%): 96.7 (frustum 30, tetrahedron 30, prism 27: box 1, a prism of 5 sides 1,
      // unknown 1); 0.16%, 1.29%; 0.07%; 0.06; 0, 0 (fast form, prism-2)
      {"new_shapes", 90, 93.5, 0.0030, 0.0350, 0.0015, 0.25, 1, 1},
      // new_shapes_view (the same kinds, one camera in any direction; "all" holds the 81 views
      // that determine their solid, the other 9 are all/undet): 91.4 (tetrahedron 26, frustum
      // 29, prism 19; box 3, prisms of other sides 2, unknown 2); 0.78%, 3.49%; 0.45%; 0.12;
      // 1, 0. The floor is issue 11's 90.
      {"new_shapes_view", 90, 90.0, 0.0160, 0.0700, 0.0090, 0.30, 2, 1},
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
  if (g.max_dim_median >= 0) {
    const Json& dim = all.at("dimension_error");
    EXPECT_LE(number(dim.at("median"), "dimension error median"), g.max_dim_median) << figures;
    EXPECT_LE(number(dim.at("p90"), "dimension error p90"), g.max_dim_p90) << figures;
  }
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
  // An honest unknown, never one of the six, for a solid that is none of them.
  if (g.condition == "negatives") {
    for (const auto& [shape, count] : all.at("wrong_as").items())
      for (const char* six : {"box", "tetrahedron", "pentagonal_prism", "cone", "cylinder", "sphere"})
        EXPECT_NE(shape, six) << count << " negatives reported as " << shape;
  }
  // Every single-object synthetic cloud holds one solid: in "all", or (a view that does not
  // determine its solid) in "all/undet".
  if (g.condition != "multi" && g.condition != "real") {
    std::size_t objects = all.at("objects").get<std::size_t>();
    for (const Json& row : c.at("rows"))
      if (row.at("shape") == "all/undet") objects += row.at("objects").get<std::size_t>();
    EXPECT_EQ(objects, g.clouds);
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
