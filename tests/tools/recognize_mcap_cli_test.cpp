// cloudshape-recognize on MCAP recordings: one JSON line per PointCloud2 message, the same
// objects as from the same points in a PCD file, and damaged recordings reported on one line.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "io/cloud_writers.hpp"
#include "io/mcap_writer.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/ros2_schemas.hpp"
#include "io/pointcloud2_encode.hpp"
#include "process.hpp"
#include "solid_samples.hpp"
#include "report/result_json.hpp"

namespace cloudshape {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using testing::lines_of;
using testing::ProcessResult;
using testing::sample;


// `points` at pixels i + i / 4 of a width-wide grid (every fifth pixel empty), as a depth frame.
GridLayout grid_for(std::size_t n, std::uint32_t width) {
  GridLayout grid;
  grid.width = width;
  for (std::uint32_t i = 0; i < n; ++i) grid.pixel.push_back(i + i / 4);
  grid.height = (grid.pixel.back() / width) + 1;
  return grid;
}

std::string cdr_of(const PointList& points, const GridLayout& grid, const io::PointCloud2Layout& layout) {
  return io::pointcloud2_to_cdr(io::encode_pointcloud2(points, grid, layout, {{3, 0}, "camera"}));
}

// The organized PCD of the same frame: every pixel, the empty ones NaN.
void write_organized_pcd(const std::string& path, const PointList& points, const GridLayout& grid) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PointList full(grid.width * grid.height, Point(nan, nan, nan));
  for (std::size_t i = 0; i < points.size(); ++i) full[grid.pixel[i]] = points[i];
  io::write_labelled_pcd(path, full, std::vector<std::uint32_t>(full.size(), 0), grid.width, grid.height,
                         io::PcdEncoding::binary);
}

// A result without what differs between runs and inputs: the source and the timings.
Json comparable(Json j) {
  j.erase("source");
  j.erase("timings_ms");
  return j;
}

class RecognizeMcapCli : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    std::string tmpl = (fs::temp_directory_path() / "cloudshape-recognize-mcap-XXXXXX").string();
    ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
    dir_ = new fs::path(tmpl);
    box_ = new PointList(sample(synth::ShapeKind::box, 6000, 1));
    cylinder_ = new PointList(sample(synth::ShapeKind::cylinder, 6000, 2));
    io::write_pcd(path("box.pcd"), *box_, io::PcdEncoding::binary);
    io::write_pcd(path("cylinder64.pcd"), *cylinder_, io::PcdEncoding::binary, true);
    write_organized_pcd(path("box_organized.pcd"), *box_, grid_for(box_->size(), 100));

    io::McapWriterOptions options;
    options.compression = io::McapCompression::lz4;
    options.chunk_size = 1;  // a chunk per message: a cut keeps the chunks before it
    io::McapWriter writer(path("rec.mcap"), options);
    const auto schema =
        writer.add_schema(io::kPointCloud2SchemaName, "ros2msg", io::ros2_schema_text(io::kPointCloud2SchemaName));
    const auto other = writer.add_schema("std_msgs/msg/String", "ros2msg", "string data\n");
    const auto points = writer.add_channel(schema, "/camera/points", "cdr");
    const auto log = writer.add_channel(other, "/rosout", "cdr");
    writer.write(points, 100, 100, cdr_of(*box_, {}, {}));
    writer.write(log, 110, 110, "not a cloud");
    writer.write(points, 200, 200, cdr_of(*cylinder_, {}, io::float64_layout()));
    writer.write(points, 300, 300, cdr_of(*box_, grid_for(box_->size(), 100), {}));
    PointCloud2Bad bad;
    writer.write(points, 400, 400, bad.bytes());
    writer.write(points, 500, 500, cdr_of(*box_, {}, {}));
    writer.close();

    std::ifstream in(path("rec.mcap"), std::ios::binary);
    const std::string whole((std::istreambuf_iterator<char>(in)), {});
    std::ofstream(path("cut.mcap"), std::ios::binary) << whole.substr(0, whole.size() * 3 / 4);
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(*dir_, ec);
    delete dir_;
    delete box_;
    delete cylinder_;
  }
  static std::string path(const std::string& name) { return (*dir_ / name).string(); }

  // A PointCloud2 without its z field: the recording is fine, this message is not.
  struct PointCloud2Bad {
    std::string bytes() const {
      io::PointCloud2 msg = io::encode_pointcloud2(PointList(10, Point(1, 2, 3)), {}, {}, {});
      msg.fields.erase(msg.fields.begin() + 2);
      return io::pointcloud2_to_cdr(msg);
    }
  };

  static ProcessResult run(const std::vector<std::string>& files) {
    std::vector<std::string> args{CLOUDSHAPE_RECOGNIZE_BIN};
    args.insert(args.end(), files.begin(), files.end());
    return testing::run_process(args);
  }

  static std::vector<Json> results(const ProcessResult& r) {
    std::vector<Json> out;
    for (const auto& line : lines_of(r.out)) {
      Json j = Json::parse(line);
      EXPECT_EQ(report::schema_problems(j), std::vector<std::string>{}) << line;
      out.push_back(std::move(j));
    }
    return out;
  }

  static fs::path* dir_;
  static PointList* box_;
  static PointList* cylinder_;
};
fs::path* RecognizeMcapCli::dir_ = nullptr;
PointList* RecognizeMcapCli::box_ = nullptr;
PointList* RecognizeMcapCli::cylinder_ = nullptr;

// The same points give the same objects, to the last digit: one pipeline, one decoding.
TEST_F(RecognizeMcapCli, EachPointCloud2MessageGivesWhatItsPcdGives) {
  const ProcessResult from_mcap = run({path("rec.mcap")});
  const ProcessResult from_pcd = run({path("box.pcd"), path("cylinder64.pcd"), path("box_organized.pcd")});
  ASSERT_EQ(from_pcd.exit_code, 0) << from_pcd.err;
  EXPECT_EQ(from_mcap.exit_code, 2) << "message 3 has no z field";
  const auto mcap = results(from_mcap);
  const auto pcd = results(from_pcd);
  ASSERT_EQ(mcap.size(), 4u) << from_mcap.err;
  ASSERT_EQ(pcd.size(), 3u);
  EXPECT_EQ(mcap[0]["source"], "rec.mcap#0");
  EXPECT_EQ(mcap[1]["source"], "rec.mcap#1");
  EXPECT_EQ(mcap[2]["source"], "rec.mcap#2");
  EXPECT_EQ(mcap[3]["source"], "rec.mcap#4");
  EXPECT_EQ(comparable(mcap[0]), comparable(pcd[0]));
  EXPECT_EQ(comparable(mcap[1]), comparable(pcd[1]));
  EXPECT_EQ(comparable(mcap[2]), comparable(pcd[2]));
  EXPECT_EQ(comparable(mcap[3]), comparable(pcd[0]));
  EXPECT_EQ(mcap[0]["objects"][0]["shape"], "box");
  EXPECT_EQ(mcap[1]["objects"][0]["shape"], "cylinder");
  const auto err = lines_of(from_mcap.err);
  ASSERT_EQ(err.size(), 1u) << from_mcap.err;
  EXPECT_EQ(err[0].rfind("cloudshape-recognize: " + path("rec.mcap") + ": message 3 (/camera/points), fields: no field named 'z'", 0), 0u)
      << err[0];
}

TEST_F(RecognizeMcapCli, ATruncatedRecordingKeepsTheCloudsBeforeTheCut) {
  const ProcessResult r = run({path("cut.mcap"), path("box.pcd")});
  EXPECT_EQ(r.exit_code, 2);
  const auto got = results(r);
  ASSERT_GE(got.size(), 2u);
  EXPECT_EQ(got.front()["source"], "cut.mcap#0");
  EXPECT_EQ(got.back()["source"], "box.pcd");
  std::size_t cut_lines = 0;
  for (const auto& line : lines_of(r.err)) {
    if (line.rfind("cloudshape-recognize: " + path("cut.mcap") + ": ", 0) == 0) {
      ++cut_lines;
      EXPECT_NE(line.find("truncated"), std::string::npos) << line;
    }
  }
  EXPECT_EQ(cut_lines, 1u) << r.err;
}

TEST_F(RecognizeMcapCli, ANonMcapFileNamedMcapIsOneError) {
  std::ofstream(path("fake.mcap")) << "VERSION 0.7\n";
  const ProcessResult r = run({path("fake.mcap")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(r.err, "cloudshape-recognize: " + path("fake.mcap") + ": byte 0: not an MCAP file: it does not start with the MCAP magic\n");
}

// --start: the clouds from that message or time on, numbered from the file's first message; the
// file has one chunk per message and its indexes, so the chunks before the start are not read.
TEST_F(RecognizeMcapCli, StartsAtAMessageOrATime) {
  const ProcessResult at_message = run({"--start", "2", path("rec.mcap")});
  EXPECT_EQ(at_message.exit_code, 2) << "message 3 has no z field";
  auto got = results(at_message);
  ASSERT_EQ(got.size(), 2u) << at_message.err;
  EXPECT_EQ(got[0]["source"], "rec.mcap#2");
  EXPECT_EQ(got[1]["source"], "rec.mcap#4");
  EXPECT_EQ(comparable(got[0]), comparable(results(run({path("box_organized.pcd")}))[0]));
  // Log times 100 ... 500 ns: 0.00000035 s after the first message is 450 ns: message 4 on.
  const ProcessResult at_time = run({"--start", "0.00000035s", path("rec.mcap")});
  EXPECT_EQ(at_time.exit_code, 0) << at_time.err;
  got = results(at_time);
  ASSERT_EQ(got.size(), 1u) << at_time.err;
  EXPECT_EQ(got[0]["source"], "rec.mcap#4");
  EXPECT_TRUE(at_time.err.empty()) << at_time.err;
}

TEST_F(RecognizeMcapCli, ABadStartIsRefused) {
  const ProcessResult r = run({"--start", "-3", path("rec.mcap")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(r.err, "cloudshape-recognize: --start '-3': expected a message index (e.g. 150) or seconds into the "
                   "recording (e.g. 2.5s)\n");
}

// A recording without a usable index (here cut short: no Footer) is read from its start, said once.
TEST_F(RecognizeMcapCli, AStartWithoutAnIndexReadsFromTheBeginning) {
  const ProcessResult r = run({"--start", "1", path("cut.mcap")});
  EXPECT_EQ(r.exit_code, 2);
  const auto got = results(r);
  ASSERT_GE(got.size(), 1u) << r.err;
  EXPECT_EQ(got.front()["source"], "cut.mcap#1");
  EXPECT_NE(r.err.find(path("cut.mcap") + ": no usable index (the file does not end with a Footer and the MCAP "
                       "magic): read from the start to --start"),
            std::string::npos)
      << r.err;
}

TEST(RecognizeRecordCli, RecordOptionsAreChecked) {
  const ProcessResult clouds_alone =
      testing::run_process({CLOUDSHAPE_RECOGNIZE_BIN, "--record-clouds", "/nonexistent/box.pcd"});
  EXPECT_EQ(clouds_alone.exit_code, 2);
  EXPECT_NE(clouds_alone.err.find("--record-clouds requires --record"), std::string::npos) << clouds_alone.err;
  const ProcessResult unwritable =
      testing::run_process({CLOUDSHAPE_RECOGNIZE_BIN, "--record", "/nonexistent/dir/out.mcap", "/nonexistent/box.pcd"});
  EXPECT_EQ(unwritable.exit_code, 2);
  EXPECT_EQ(unwritable.err, "cloudshape-recognize: /nonexistent/dir/out.mcap: cannot create the recording\n");
  EXPECT_TRUE(unwritable.out.empty());
}

}  // namespace
}  // namespace cloudshape
