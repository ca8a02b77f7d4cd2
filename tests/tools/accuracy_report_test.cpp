// What cloudshape-bench --accuracy reports from finished tallies (tools/bench/accuracy_report):
// rates, quantiles of the errors, counts and the row order, against figures worked by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "accuracy_report.hpp"
#include "bench_stats.hpp"

namespace cloudshape::bench {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kExact = 1e-12;

TEST(AccuracyReport, PercentileInterpolatesBetweenOrderStatistics) {
  const std::vector<double> v = {0.3, 0.0, 0.2, 0.1};
  EXPECT_NEAR(percentile(v, 0.5), 0.15, kExact);
  EXPECT_NEAR(percentile(v, 0.9), 0.27, kExact);  // 0.2 + 0.7 x (0.3 - 0.2)
  EXPECT_NEAR(percentile(v, 0.0), 0.0, kExact);
  EXPECT_NEAR(percentile(v, 1.0), 0.3, kExact);
}

ConditionReport sample_condition() {
  ConditionReport c;
  c.name = "noise";
  c.clouds = 5;
  Tally& cone = c.tallies["cone"];
  cone.objects = 2;
  cone.right = 1;
  cone.matched = 2;
  cone.shaped = 2;
  cone.partial = 1;
  cone.wrong_as = {{"cylinder", 1}};
  cone.dimension_errors = {0.02, 0.04};
  cone.centre_errors = {0.01};
  cone.axis_errors_deg = {3.0};
  Tally& box = c.tallies["box"];
  box.objects = 3;
  box.right = 2;
  box.matched = 2;
  box.shaped = 2;
  box.missed = 1;
  box.false_objects = 2;
  box.wrong_as = {{"missed", 1}};
  box.dimension_errors = {0.0, 0.01, 0.03};
  box.centre_errors = {0.0, 0.02};
  box.axis_errors_deg = {1.0, 2.0};
  return c;
}

TEST(AccuracyReport, JsonRowsInShapeOrderThenAll) {
  const Json out = accuracy_json({sample_condition()}, Json{{"count", 1}});
  EXPECT_EQ(out.at("settings").at("count"), 1);
  ASSERT_EQ(out.at("conditions").size(), 1u);
  const Json& c = out.at("conditions")[0];
  EXPECT_EQ(c.at("name"), "noise");
  EXPECT_EQ(c.at("clouds"), 5);
  std::vector<std::string> shapes;
  for (const auto& row : c.at("rows")) shapes.push_back(row.at("shape"));
  EXPECT_EQ(shapes, (std::vector<std::string>{"box", "cone", "all"}));
}

TEST(AccuracyReport, ShapeRowRatesAndQuantiles) {
  const Json cone = accuracy_json({sample_condition()}, {}).at("conditions")[0].at("rows")[1];
  EXPECT_EQ(cone.at("shape"), "cone");
  EXPECT_EQ(cone.at("objects"), 2);
  EXPECT_EQ(cone.at("right"), 1);
  EXPECT_NEAR(cone.at("recognized_pct").get<double>(), 50.0, kExact);
  EXPECT_NEAR(cone.at("dimension_error").at("median").get<double>(), 0.03, kExact);
  EXPECT_NEAR(cone.at("dimension_error").at("p90").get<double>(), 0.038, kExact);
  EXPECT_EQ(cone.at("dimension_error").at("count"), 2);
  EXPECT_NEAR(cone.at("centre_error_median").get<double>(), 0.01, kExact);
  EXPECT_NEAR(cone.at("axis_error_deg_median").get<double>(), 3.0, kExact);
  EXPECT_NEAR(cone.at("partial_pct").get<double>(), 50.0, kExact);
  EXPECT_EQ(cone.at("wrong_as"), (Json{{"cylinder", 1}}));
}

TEST(AccuracyReport, AllRowPoolsEveryShape) {
  const Json all = accuracy_json({sample_condition()}, {}).at("conditions")[0].at("rows")[2];
  EXPECT_EQ(all.at("shape"), "all");
  EXPECT_EQ(all.at("objects"), 5);
  EXPECT_EQ(all.at("right"), 3);
  EXPECT_NEAR(all.at("recognized_pct").get<double>(), 60.0, kExact);
  // Pooled errors {0, 0.01, 0.02, 0.03, 0.04}: median 0.02, p90 0.036.
  EXPECT_NEAR(all.at("dimension_error").at("median").get<double>(), 0.02, kExact);
  EXPECT_NEAR(all.at("dimension_error").at("p90").get<double>(), 0.036, kExact);
  EXPECT_EQ(all.at("dimension_error").at("count"), 5);
  EXPECT_NEAR(all.at("centre_error_median").get<double>(), 0.01, kExact);
  EXPECT_NEAR(all.at("axis_error_deg_median").get<double>(), 2.0, kExact);
  EXPECT_EQ(all.at("false_objects"), 2);
  EXPECT_EQ(all.at("missed_objects"), 1);
  EXPECT_NEAR(all.at("partial_pct").get<double>(), 25.0, kExact);  // 1 of 4 shaped
  EXPECT_EQ(all.at("wrong_as"), (Json{{"cylinder", 1}, {"missed", 1}}));
}

// No right-shape object: the errors are null, not 0 (which would read as perfect).
TEST(AccuracyReport, NoErrorsAreNullNotZero) {
  ConditionReport c;
  c.name = "clean";
  c.tallies["sphere"].objects = 1;
  c.tallies["sphere"].missed = 1;
  const Json row = accuracy_json({c}, {}).at("conditions")[0].at("rows")[0];
  EXPECT_EQ(row.at("shape"), "sphere");
  EXPECT_NEAR(row.at("recognized_pct").get<double>(), 0.0, kExact);
  EXPECT_TRUE(row.at("dimension_error").at("median").is_null());
  EXPECT_TRUE(row.at("dimension_error").at("p90").is_null());
  EXPECT_TRUE(row.at("centre_error_median").is_null());
  EXPECT_TRUE(row.at("axis_error_deg_median").is_null());
}

TEST(AccuracyReport, DimensionsText) {
  EXPECT_EQ(dimensions_text({{"length", 30.0}, {"width", 20.25}}), "length 30, width 20.25");
  EXPECT_EQ(dimensions_text({}), "-");
}

}  // namespace
}  // namespace cloudshape::bench
