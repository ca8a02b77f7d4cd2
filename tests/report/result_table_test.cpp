// The human table of --format table: one aligned line per object, numbers in the file's unit.
#include <gtest/gtest.h>

#include "report/result_table.hpp"

namespace cloudshape::report {
namespace {

pipeline::ObjectResult object(const std::string& shape,
                              std::vector<std::pair<std::string, double>> dimensions,
                              double confidence, bool partial, const std::string& reason = "") {
  pipeline::ObjectResult o;
  o.shape = shape;
  o.dimensions = std::move(dimensions);
  o.confidence = confidence;
  o.partial = partial;
  o.reason = reason;
  return o;
}

pipeline::RecognitionResult two_objects() {
  pipeline::RecognitionResult r;
  r.source = "scene.pcd";
  r.timings.total_ms = 41.26;
  r.objects.push_back(
      object("box", {{"length", 30.0}, {"width", 20.0}, {"height", 10.0}}, 0.971, false));
  r.objects.push_back(object("sphere", {{"radius", 0.032951}}, 0.5, true));
  return r;
}

TEST(ResultTable, OneLinePerObjectWithEveryColumn) {
  const TableLayout layout = table_layout({"scene.pcd", "a.pcd"});
  const auto rows = table_rows(two_objects(), layout);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].rfind("scene.pcd  box ", 0), 0u) << rows[0];
  EXPECT_NE(rows[0].find("length 30.00 width 20.00 height 10.00"), std::string::npos) << rows[0];
  EXPECT_NE(rows[0].find(" 0.97 "), std::string::npos) << rows[0];
  EXPECT_NE(rows[0].find(" no "), std::string::npos) << rows[0];
  EXPECT_EQ(rows[0].substr(rows[0].size() - 4), "41.3") << rows[0];
  // A sub-millimetre-scale length keeps four significant digits, not "0.03".
  EXPECT_NE(rows[1].find("radius 0.03295"), std::string::npos) << rows[1];
  EXPECT_NE(rows[1].find(" yes "), std::string::npos) << rows[1];
}

TEST(ResultTable, ColumnsLineUpWithTheHeader) {
  const TableLayout layout = table_layout({"scene.pcd", "a_much_longer_file_name.ply"});
  const std::string header = table_header(layout);
  const auto rows = table_rows(two_objects(), layout);
  for (const char* column : {"shape", "dimensions"}) {
    const std::size_t at = header.find(column);
    ASSERT_NE(at, std::string::npos);
    for (const auto& r : rows) EXPECT_NE(r[at], ' ') << column << " column in: " << r;
    for (const auto& r : rows) EXPECT_EQ(r[at - 1], ' ') << column << " column in: " << r;
  }
  // The right-aligned ms column ends where the header's does.
  EXPECT_EQ(rows[0].size(), header.size());
}

TEST(ResultTable, UnknownShowsItsReasonAndEmptyCloudsStillGetALine) {
  pipeline::RecognitionResult r;
  r.source = "flat.xyz";
  r.objects.push_back(object("unknown", {}, 0.0, false, "all points coplanar"));
  const auto rows = table_rows(r, table_layout({"flat.xyz"}));
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NE(rows[0].find("unknown"), std::string::npos);
  EXPECT_EQ(rows[0].substr(rows[0].size() - 19), "all points coplanar") << rows[0];

  r.objects.clear();
  const auto empty = table_rows(r, table_layout({"flat.xyz"}));
  ASSERT_EQ(empty.size(), 1u);
  EXPECT_NE(empty[0].find("no object found"), std::string::npos) << empty[0];
}

TEST(ResultTable, LengthsOutsideThePlainRangeUseExponents) {
  EXPECT_EQ(dimensions_text(object("sphere", {{"radius", 2.5e7}}, 1, false)), "radius 2.5e+07");
  EXPECT_EQ(dimensions_text(object("sphere", {{"radius", 1234.56}}, 1, false)), "radius 1235");
  EXPECT_EQ(dimensions_text(object("unknown", {}, 0, false)), "-");
  // Rounding up to the next power of ten keeps four significant digits.
  EXPECT_EQ(dimensions_text(object("sphere", {{"radius", 9.99996}}, 1, false)), "radius 10.00");
  EXPECT_EQ(dimensions_text(object("sphere", {{"radius", 0.099996}}, 1, false)), "radius 0.1000");
}

}  // namespace
}  // namespace cloudshape::report
