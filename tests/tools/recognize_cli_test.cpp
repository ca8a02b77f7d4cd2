// cloudshape-recognize as a user runs it: exit codes, one JSON line per readable file on
// stdout, one "cloudshape-recognize: <file>: <problem>" line on stderr per unreadable file.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/cloud_writers.hpp"
#include "process.hpp"
#include "solid_samples.hpp"
#include "report/result_json.hpp"
#include "synth/random_solid.hpp"
#include "synth/sample_solid.hpp"

namespace cloudshape {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using testing::lines_of;
using testing::ProcessResult;
using testing::run_process;
using testing::sample;
using testing::solid;

const std::string kBin = CLOUDSHAPE_RECOGNIZE_BIN;
const std::string kPrefix = "cloudshape-recognize: ";


void write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

void write_xyz(const fs::path& path, const PointList& points) {
  std::ofstream f(path);
  f.precision(17);
  for (const auto& p : points) f << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
}

// ascii PCD; every `nan_every`-th point (if > 0) is written as NaN.
void write_pcd(const fs::path& path, const PointList& points, std::size_t nan_every) {
  std::ofstream f(path);
  f.precision(9);
  f << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\n"
       "TYPE F F F\nCOUNT 1 1 1\nWIDTH "
    << points.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << points.size()
    << "\nDATA ascii\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (nan_every > 0 && i % nan_every == 0) {
      f << "nan nan nan\n";
    } else {
      f << points[i].x() << ' ' << points[i].y() << ' ' << points[i].z() << '\n';
    }
  }
}

// ascii PLY mesh: the points as vertices plus a face element, which must be ignored.
void write_ply_mesh(const fs::path& path, const PointList& points) {
  std::ofstream f(path);
  f.precision(17);
  const std::size_t faces = points.size() / 3;
  f << "ply\nformat ascii 1.0\nelement vertex " << points.size()
    << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << faces
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : points) f << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (std::size_t i = 0; i < faces; ++i)
    f << "3 " << 3 * i << ' ' << 3 * i + 1 << ' ' << 3 * i + 2 << '\n';
}

class RecognizeCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string tmpl = (fs::temp_directory_path() / "cloudshape-recognize-test-XXXXXX").string();
    ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
    dir_ = new fs::path(tmpl);
    write_xyz(path("box.xyz"), sample(synth::ShapeKind::box, 6000, 1));
    write_ply_mesh(path("cylinder.ply"), sample(synth::ShapeKind::cylinder, 6000, 2));
    write_pcd(path("sphere_some_nan.pcd"), sample(synth::ShapeKind::sphere, 6000, 3), 10);
    write_pcd(path("all_nan.pcd"), sample(synth::ShapeKind::sphere, 50, 4), 1);
    write_text(path("empty.xyz"), "");
    write_text(path("garbage.pcd"), "this is not a point cloud\n\x01\x02\x03\n");
    write_text(path("bad.yaml"), "no_such_section:\n  threshold: 1\n");
    write_text(path("small_points.yaml"), "input:\n  max_points: 5999\n");
    write_text(path("small_bytes.yaml"), "input:\n  max_bytes: 1000\n");
    write_degenerate_clouds();
    write_text(path("far_point.xyz"), "0 0 0\n1 0 0\n0 1 1e200\n");
    write_truncated_files();
    write_text(path("broken.yaml"), "preprocess: [unclosed\n");
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(*dir_, ec);
    delete dir_;
  }
  static std::string path(const std::string& name) { return (*dir_ / name).string(); }

  // Readable clouds with no solid in them (the reason each must give is in the test).
  static void write_degenerate_clouds() {
    write_xyz(path("one_point.xyz"), {Point(1, 2, 3)});
    write_xyz(path("three_points.xyz"), {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)});
    write_xyz(path("repeated_point.xyz"), PointList(3000, Point(4, 5, 6)));
    PointList line, plane;
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 3000; ++i) {
      line.emplace_back(0.01 * i, 0.02 * i, -0.03 * i);
      const double a = u(rng), b = u(rng);
      plane.emplace_back(a, b, 0.5 * a - 0.25 * b + 2.0);
    }
    write_xyz(path("collinear.xyz"), line);
    write_xyz(path("coplanar.xyz"), plane);
  }

  // Binary files cut short: the header promises more points than the data holds.
  static void write_truncated_files() {
    const PointList points = sample(synth::ShapeKind::box, 2000, 5);
    for (const std::string name : {"truncated.pcd", "truncated.ply"}) {
      const std::string whole = path("whole_" + name);
      if (name == "truncated.pcd") {
        io::write_pcd(whole, points, io::PcdEncoding::binary);
      } else {
        io::write_ply(whole, points, true);
      }
      std::ifstream in(whole, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), {});
      write_text(path(name), bytes.substr(0, bytes.size() / 2));
    }
  }

  static ProcessResult run(std::vector<std::string> args) {
    args.insert(args.begin(), kBin);
    return run_process(args);
  }

  // Every stdout line must be one schema-conforming result; returns them parsed.
  static std::vector<Json> results(const ProcessResult& r) {
    std::vector<Json> out;
    for (const auto& line : lines_of(r.out)) {
      Json j;
      EXPECT_NO_THROW(j = Json::parse(line)) << "not JSON: " << line;
      EXPECT_EQ(report::schema_problems(j), std::vector<std::string>{}) << line;
      EXPECT_NO_THROW(report::result_from_json(j)) << line;
      out.push_back(j);
    }
    return out;
  }

  // The stderr lines that report `file` as failed.
  static std::vector<std::string> failures_for(const ProcessResult& r, const std::string& file) {
    std::vector<std::string> found;
    for (const auto& line : lines_of(r.err)) {
      if (line.rfind(kPrefix + file + ": ", 0) == 0) found.push_back(line);
    }
    return found;
  }

  static fs::path* dir_;
};
fs::path* RecognizeCli::dir_ = nullptr;

TEST_F(RecognizeCli, GoodFilesGiveOneConformingLineEachInOrder) {
  const ProcessResult r = run({path("box.xyz"), path("cylinder.ply"), path("sphere_some_nan.pcd")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto res = results(r);
  ASSERT_EQ(res.size(), 3u) << r.out;
  // source is the file's base name.
  EXPECT_EQ(res[0]["source"], "box.xyz");
  EXPECT_EQ(res[1]["source"], "cylinder.ply");
  EXPECT_EQ(res[2]["source"], "sphere_some_nan.pcd");
  EXPECT_EQ(res[0]["points_in"].get<std::size_t>(), 6000u);
  EXPECT_EQ(res[1]["points_in"].get<std::size_t>(), 6000u);  // vertices only, faces ignored
  EXPECT_EQ(res[2]["points_in"].get<std::size_t>(), 5400u);  // the NaN points are dropped
  // Clean, complete surfaces: the shape, and every dimension and the centre within 1% (the
  // synthetic suite's figure; the PCD holds floats, 9 digits).
  const synth::SolidSpec truths[] = {solid(synth::ShapeKind::box, 1),
                                     solid(synth::ShapeKind::cylinder, 2),
                                     solid(synth::ShapeKind::sphere, 3)};
  for (std::size_t i = 0; i < res.size(); ++i) {
    const synth::SolidSpec& truth = truths[i];
    SCOPED_TRACE(res[i]["source"].get<std::string>());
    ASSERT_EQ(res[i]["objects"].size(), 1u) << res[i].dump();
    const Json& o = res[i]["objects"][0];
    EXPECT_EQ(o["shape"], synth::to_string(truth.kind));
    ASSERT_EQ(o["dimensions"].size(), truth.dimensions.size()) << o.dump();
    for (const auto& [name, value] : truth.dimensions)
      EXPECT_NEAR(o["dimensions"].value(name, 0.0), value, 0.01 * value) << name;
    const Eigen::Vector3d center(o["pose"]["center"][0].get<double>(),
                                 o["pose"]["center"][1].get<double>(),
                                 o["pose"]["center"][2].get<double>());
    EXPECT_LT((center - truth.pose.center).norm(), 0.01 * synth::characteristic_size(truth));
  }
}

TEST_F(RecognizeCli, UnreadableFilesAreReportedAndTheOthersStillProcessed) {
  const std::vector<std::string> bad = {path("missing.pcd"), path("garbage.pcd"),
                                        path("all_nan.pcd"), path("empty.xyz")};
  const ProcessResult r =
      run({path("box.xyz"), bad[0], bad[1], path("cylinder.ply"), bad[2], bad[3]});
  EXPECT_EQ(r.exit_code, 2);
  const auto res = results(r);
  ASSERT_EQ(res.size(), 2u) << r.out;
  EXPECT_EQ(res[0]["source"], "box.xyz");
  EXPECT_EQ(res[1]["source"], "cylinder.ply");
  for (const auto& file : bad) {
    const auto lines = failures_for(r, file);
    EXPECT_EQ(lines.size(), 1u) << "for " << file << " in stderr:\n" << r.err;
    for (const auto& line : lines) EXPECT_GT(line.size(), kPrefix.size() + file.size() + 2);
  }
}

TEST_F(RecognizeCli, OnlyBadFilesGiveNoStdout) {
  const ProcessResult r = run({path("all_nan.pcd")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  const auto lines = failures_for(r, path("all_nan.pcd"));
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_NE(lines[0].find("no usable points"), std::string::npos) << lines[0];
}

TEST_F(RecognizeCli, TruncatedFilesAreReportedOnOneLineEach) {
  const ProcessResult r = run({path("truncated.pcd"), path("box.xyz"), path("truncated.ply")});
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_EQ(results(r).size(), 1u) << r.out;
  for (const std::string file : {"truncated.pcd", "truncated.ply"}) {
    const auto lines = failures_for(r, path(file));
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_NE(lines[0].find("truncated"), std::string::npos) << lines[0];
  }
}

TEST_F(RecognizeCli, InputLimitsFromTheConfigurationRefuseBiggerFiles) {
  // box.xyz holds 6000 points; the limit is 5999. The file under the limit is still processed.
  const ProcessResult points = run({"--config", path("small_points.yaml"), path("box.xyz"), path("three_points.xyz")});
  EXPECT_EQ(points.exit_code, 2);
  EXPECT_EQ(results(points).size(), 1u) << points.out;
  auto lines = failures_for(points, path("box.xyz"));
  ASSERT_EQ(lines.size(), 1u) << points.err;
  EXPECT_NE(lines[0].find("more than the limit of 5999 points"), std::string::npos) << lines[0];

  const ProcessResult bytes = run({"--config", path("small_bytes.yaml"), path("box.xyz"), path("one_point.xyz")});
  EXPECT_EQ(bytes.exit_code, 2);
  EXPECT_EQ(results(bytes).size(), 1u) << bytes.out;
  lines = failures_for(bytes, path("box.xyz"));
  ASSERT_EQ(lines.size(), 1u) << bytes.err;
  EXPECT_NE(lines[0].find("more than the limit of 1000 bytes"), std::string::npos) << lines[0];
}

TEST_F(RecognizeCli, CoordinatesBeyondTheLimitAreRefused) {
  const ProcessResult r = run({path("far_point.xyz"), path("one_point.xyz")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(results(r).size(), 1u) << r.out;
  const auto lines = failures_for(r, path("far_point.xyz"));
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_NE(lines[0].find("beyond input.max_coordinate 1e+30"), std::string::npos) << lines[0];
}

TEST_F(RecognizeCli, CloudsWithNoSolidAreUnknownWithTheirReason) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"one_point.xyz", "too few points"},   {"three_points.xyz", "too few points"},
      {"repeated_point.xyz", "all points coincide"}, {"collinear.xyz", "collinear"},
      {"coplanar.xyz", "coplanar"}};
  std::vector<std::string> files;
  for (const auto& [file, reason] : cases) files.push_back(path(file));
  const ProcessResult r = run(files);
  EXPECT_EQ(r.exit_code, 0) << r.err;  // readable files: unknown is still a success
  const auto res = results(r);
  ASSERT_EQ(res.size(), cases.size()) << r.out;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].first);
    EXPECT_EQ(res[i]["source"], cases[i].first);
    ASSERT_EQ(res[i]["objects"].size(), 1u) << res[i].dump();
    EXPECT_EQ(res[i]["objects"][0]["shape"], "unknown");
    EXPECT_TRUE(res[i]["objects"][0]["dimensions"].empty());
    EXPECT_NE(res[i]["objects"][0]["reason"].get<std::string>().find(cases[i].second), std::string::npos)
        << res[i].dump();
  }
}

TEST_F(RecognizeCli, BadConfigurationStopsBeforeAnyFile) {
  for (const std::string& cfg : {path("bad.yaml"), path("broken.yaml"), path("missing.yaml")}) {
    const ProcessResult r = run({"--config", cfg, path("box.xyz")});
    EXPECT_EQ(r.exit_code, 2) << cfg;
    EXPECT_EQ(r.out, "") << cfg;
    const auto lines = lines_of(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind(kPrefix, 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(cfg), std::string::npos) << lines[0];
  }
}

TEST_F(RecognizeCli, ShippedConfigurationLoads) {
  const fs::path shipped = fs::path(CLOUDSHAPE_SOURCE_DIR) / "config" / "pipeline.yaml";
  ASSERT_TRUE(fs::exists(shipped)) << shipped;
  const ProcessResult r = run({"--config", shipped.string(), path("box.xyz")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(results(r).size(), 1u);
}

TEST_F(RecognizeCli, PrettyPrintsTheSameObject) {
  const ProcessResult pretty = run({"--pretty", path("box.xyz")});
  EXPECT_EQ(pretty.exit_code, 0) << pretty.err;
  EXPECT_GT(lines_of(pretty.out).size(), 5u);
  Json j;
  ASSERT_NO_THROW(j = Json::parse(pretty.out)) << pretty.out;
  EXPECT_EQ(report::schema_problems(j), std::vector<std::string>{});
  const ProcessResult compact = run({path("box.xyz")});
  ASSERT_EQ(results(compact).size(), 1u);
  Json c = Json::parse(compact.out);
  j.erase("timings_ms");
  c.erase("timings_ms");
  EXPECT_EQ(j, c);  // the same answer both times, timings aside
}

// --format table: a header, then one line per object carrying what the JSON says (dimensions
// to four significant digits); unreadable files still go to stderr and set the exit status.
TEST_F(RecognizeCli, TableFormatGivesOneLinePerObjectWithTheJsonFigures) {
  const std::vector<std::string> files = {path("box.xyz"), path("cylinder.ply"),
                                          path("coplanar.xyz")};
  std::vector<std::string> args = {"--format", "table"};
  args.insert(args.end(), files.begin(), files.end());
  args.push_back(path("missing.pcd"));
  const ProcessResult table = run(args);
  EXPECT_EQ(table.exit_code, 2) << table.err;
  EXPECT_EQ(failures_for(table, path("missing.pcd")).size(), 1u) << table.err;
  const auto rows = lines_of(table.out);
  const auto json = results(run(files));
  ASSERT_EQ(json.size(), 3u);
  ASSERT_EQ(rows.size(), 4u) << table.out;  // header + one object per cloud
  EXPECT_EQ(rows[0].rfind("file", 0), 0u) << rows[0];
  for (const char* column : {"shape", "dimensions", "confidence", "partial", "ms"})
    EXPECT_NE(rows[0].find(column), std::string::npos) << column;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const std::string& row = rows[i + 1];
    std::istringstream words(row);
    std::string source, shape;
    words >> source >> shape;
    const Json& o = json[i]["objects"][0];
    EXPECT_EQ(source, json[i]["source"].get<std::string>()) << row;
    EXPECT_EQ(shape, o["shape"].get<std::string>()) << row;
    for (const auto& [name, value] : o["dimensions"].items()) {
      const std::size_t at = row.find(" " + name + " ");
      ASSERT_NE(at, std::string::npos) << name << " in: " << row;
      const double shown = std::stod(row.substr(at + name.size() + 2));
      EXPECT_NEAR(shown, value.get<double>(), 1e-3 * value.get<double>()) << name << ": " << row;
    }
    const std::string partial = o["partial"].get<bool>() ? " yes " : " no ";
    EXPECT_NE(row.find(partial), std::string::npos) << row;
  }
  EXPECT_NE(rows[3].find("coplanar"), std::string::npos) << "the unknown's reason: " << rows[3];
  EXPECT_EQ(table.out.find('{'), std::string::npos) << "no JSON in the table";
}

// A recording's clouds are named FILE#INDEX, longer than the file's name: the columns still
// line up with the header.
TEST_F(RecognizeCli, TableColumnsLineUpForARecordingsClouds) {
  const ProcessResult record =
      run({"--record", path("table.mcap"), "--record-clouds", path("box.xyz")});
  ASSERT_EQ(record.exit_code, 0) << record.err;
  const ProcessResult table = run({"--format", "table", path("table.mcap"), path("box.xyz")});
  EXPECT_EQ(table.exit_code, 0) << table.err;
  const auto rows = lines_of(table.out);
  ASSERT_EQ(rows.size(), 3u) << table.out;
  const std::size_t shape_column = rows[0].find("shape");
  EXPECT_EQ(rows[1].rfind("table.mcap#0 ", 0), 0u) << rows[1];
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_EQ(rows[i].find("  box ") + 2, shape_column) << table.out;
}

TEST_F(RecognizeCli, UnknownFormatIsACommandLineError) {
  const ProcessResult r = run({"--format", "xml", path("box.xyz")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(RecognizeCli, VerboseLogsStayOffStdout) {
  const ProcessResult r = run({"--verbose", path("box.xyz"), path("missing.pcd")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(results(r).size(), 1u);
}

TEST_F(RecognizeCli, CommandLineErrors) {
  const ProcessResult none = run({});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.out.find('{'), std::string::npos);
  const ProcessResult unknown = run({"--no-such-flag", path("box.xyz")});
  EXPECT_EQ(unknown.exit_code, 2);
  const ProcessResult help = run({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--config"), std::string::npos);
}

}  // namespace
}  // namespace cloudshape
