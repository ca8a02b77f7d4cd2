// cloudshape-mcap-bench: the recordings of the MCAP benchmark (tools/bench_mcap.sh) and the speed
// of reading them.
//   cloudshape-mcap-bench write FRAME.pcd... --frames N --rate HZ [--compression none|lz4|zstd] -o OUT.mcap
//   cloudshape-mcap-bench read FILE.mcap [--reps N] [--decode] [--start N]
// write: N PointCloud2 messages (the frames in turn; float32 x y z rgb, 16 bytes a point, organized
// frames keep their grid) 1/HZ apart on /camera/depth/points. read: the median of N reads of the
// whole file (every message visited; --decode: every PointCloud2 decoded into points too), as
// file MB/s (MB = 10^6 bytes) on stdout, one JSON line; --start N: from message N on, through
// the index (the JSON says whether it was used), to time a seek.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "io/cloud_reader.hpp"
#include "io/mcap_clouds.hpp"
#include "io/mcap_reader.hpp"
#include "io/mcap_writer.hpp"
#include "io/pointcloud2_cdr.hpp"
#include "io/pointcloud2_encode.hpp"
#include "io/ros2_schemas.hpp"

namespace {
namespace cs = cloudshape;

int write_recording(const std::vector<std::string>& frames, std::size_t count, double rate,
                    const std::string& compression, const std::string& out) {
  std::vector<std::string> messages;
  for (const std::string& path : frames) {
    const cs::io::CloudFile cloud = cs::io::read_cloud(path);
    messages.push_back(cs::io::pointcloud2_to_cdr(
        cs::io::encode_pointcloud2(cloud.points, cloud.grid, {}, {{0, 0}, "camera_depth_optical_frame"})));
  }
  cs::io::McapWriterOptions options;
  options.compression = compression == "lz4"    ? cs::io::McapCompression::lz4
                        : compression == "zstd" ? cs::io::McapCompression::zstd
                                                : cs::io::McapCompression::none;
  cs::io::McapWriter writer(out, options);
  const auto schema = writer.add_schema(cs::io::kPointCloud2SchemaName, "ros2msg",
                                        cs::io::ros2_schema_text(cs::io::kPointCloud2SchemaName));
  const auto channel = writer.add_channel(schema, "/camera/depth/points", "cdr");
  const std::uint64_t start = 1'700'000'000'000'000'000ull;
  for (std::size_t i = 0; i < count; ++i) {
    const auto t = start + static_cast<std::uint64_t>(static_cast<double>(i) * 1e9 / rate);
    writer.write(channel, t, t, messages[i % messages.size()]);
  }
  writer.close();
  return 0;
}

int read_speed(const std::string& path, int reps, bool decode, std::uint64_t from) {
  const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::vector<double> seconds;
  std::uint64_t messages = 0, points = 0;
  bool index_used = false;
  cs::io::McapStart start;
  start.message = from;
  for (int r = 0; r < reps; ++r) {
    messages = points = 0;
    const auto t0 = std::chrono::steady_clock::now();
    if (decode) {
      cs::io::read_mcap_clouds(path, {},
                               {[&](cs::io::McapCloud&& c) {
                                  ++messages;
                                  points += c.cloud.points.size();
                                },
                                [](const cs::io::ReadError& e) { throw e; }});
    } else {
      const auto visit = [&](const cs::io::McapChannel&, const cs::io::McapSchema*, const cs::io::McapMessage& m) {
        ++messages;
        points += m.data.size();  // touch the size only: the reader is what is timed
      };
      if (from > 0) {
        index_used = cs::io::read_mcap_file_from(path, start, visit).index_used;
      } else {
        cs::io::read_mcap_file(path, visit);
      }
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  nlohmann::ordered_json j;
  j["file"] = std::filesystem::path(path).filename().string();
  j["mb"] = mb;
  j["messages"] = messages;
  j["decode"] = decode;
  j["start"] = from;
  j["index_used"] = index_used;
  j["median_s"] = median;
  j["mb_per_s"] = mb / median;
  j["messages_per_s"] = static_cast<double>(messages) / median;
  std::printf("%s\n", j.dump().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes the MCAP benchmark's recordings and times reading them.", "cloudshape-mcap-bench"};
  app.require_subcommand(1);
  std::vector<std::string> frames;
  std::size_t count = 300;
  double rate = 30;
  std::string compression = "none", out, file;
  int reps = 3;
  bool decode = false;
  std::uint64_t from = 0;
  CLI::App* write = app.add_subcommand("write", "N PointCloud2 messages of the frames, 1/HZ apart");
  write->add_option("frames", frames, "organized PCD frames, used in turn")->required();
  write->add_option("--frames", count, "messages")->capture_default_str();
  write->add_option("--rate", rate, "recorded rate (Hz)")->check(CLI::PositiveNumber)->capture_default_str();
  write->add_option("--compression", compression, "none, lz4 or zstd")
      ->check(CLI::IsMember({"none", "lz4", "zstd"}))
      ->capture_default_str();
  write->add_option("-o,--output", out, "the recording")->required();
  CLI::App* read = app.add_subcommand("read", "time reading a recording");
  read->add_option("file", file, "the recording")->required();
  read->add_option("--reps", reps, "reads; the median is reported")->check(CLI::PositiveNumber)->capture_default_str();
  read->add_flag("--decode", decode, "decode every PointCloud2 into points too");
  read->add_option("--start", from, "read from this message on, through the index (not with --decode)")
      ->excludes("--decode");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (*write) return write_recording(frames, count, rate, compression, out);
    return read_speed(file, reps, decode, from);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cloudshape-mcap-bench: %s\n", e.what());
    return 1;
  }
}
