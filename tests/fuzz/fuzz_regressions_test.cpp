// Replays, in the normal build, every seed and every input the fuzzers ever stopped on
// (tests/fuzz/corpus/<target>/, tests/fuzz/regressions/<target>/): each must be read or refused
// the documented way, never crash, throw anything else or break an invariant.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fastcdr/exceptions/Exception.h>
#include <fastdds/rtps/common/SerializedPayload.h>

#include "cloudshapePubSubTypes.h"
#include "sensor_msgsPubSubTypes.h"
#include "fuzz_checks.hpp"

namespace cloudshape::fuzz {
namespace {
namespace fs = std::filesystem;

struct Target {
  const char* name;
  std::string (*check)(std::string_view);
};

std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> files;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(CLOUDSHAPE_FUZZ_DIR) / kind / target;
    if (!fs::is_directory(dir)) continue;
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.is_regular_file() && e.path().filename() != ".gitkeep") files.push_back(e.path());
    }
  }
  return files;
}

void PrintTo(const Target& target, std::ostream* os) { *os << target.name; }

class FuzzRegressions : public ::testing::TestWithParam<Target> {};

TEST_P(FuzzRegressions, EveryStoredInputIsReadOrRefused) {
  const std::vector<fs::path> files = inputs_of(GetParam().name);
  ASSERT_FALSE(files.empty()) << "no seed corpus for " << GetParam().name;
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::string problem;
    EXPECT_NO_THROW(problem = GetParam().check(bytes));
    EXPECT_EQ(problem, "");
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzRegressions,
                         ::testing::Values(Target{"pcd", check_pcd_input}, Target{"ply", check_ply_input},
                                           Target{"xyz", check_xyz_input}, Target{"mcap", check_mcap_input},
                                           Target{"ingest", check_raw_cloud_sample},
                                           Target{"pointcloud2", check_pointcloud2_sample}),
                         [](const auto& info) { return std::string(info.param.name); });

// The ingest seeds are what a DataReader would deserialize, not bytes it throws away at once.
TEST(FuzzIngestSeeds, AreCdrRawClouds) {
  const fs::path file = fs::path(CLOUDSHAPE_FUZZ_DIR) / "corpus" / "ingest" / "box_150_points.cdr";
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_FALSE(bytes.empty()) << file;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  msg::RawCloud cloud;
  msg::RawCloudPubSubType type;
  ASSERT_TRUE(type.deserialize(&payload, &cloud));
  EXPECT_EQ(cloud.header().source(), "box_150_points");
  EXPECT_EQ(cloud.header().object_count(), 1u);
  EXPECT_EQ(cloud.xyz().size(), 450u);
}

bool decodes_as_raw_cloud(const std::string& bytes, msg::RawCloud& cloud) {
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  try {
    return msg::RawCloudPubSubType().deserialize(&payload, &cloud);
  } catch (const eprosima::fastcdr::exception::Exception&) {
    return false;
  }
}

// After a change to RawCloud, seeds of the old layout would all be refused as undecodable and
// fuzz nothing beyond the header: each must decode (fuzz_ingest_seeds writes them afresh). Of the
// findings only the one about an undecodable boolean may not.
TEST(FuzzIngestSeeds, EverySeedAndFindingIsARawCloudOfTodaysLayout) {
  for (const fs::path& file : inputs_of("ingest")) {
    if (file.filename() == "bool_byte_not_0_or_1") continue;
    SCOPED_TRACE(file.string());
    std::ifstream in(file, std::ios::binary);
    msg::RawCloud cloud;
    EXPECT_TRUE(decodes_as_raw_cloud(std::string((std::istreambuf_iterator<char>(in)), {}), cloud));
  }
  msg::RawCloud frame;
  std::ifstream in(fs::path(CLOUDSHAPE_FUZZ_DIR) / "corpus" / "ingest" / "organized_frame.cdr", std::ios::binary);
  ASSERT_TRUE(decodes_as_raw_cloud(std::string((std::istreambuf_iterator<char>(in)), {}), frame));
  EXPECT_EQ(frame.width(), 20u);
  EXPECT_EQ(frame.height(), 16u);
  EXPECT_EQ(frame.pixel().size(), 150u);
}

// The PointCloud2 seeds are whole PointCloud2 samples (fuzz_pointcloud2_seeds writes them), so
// mutations reach the layout checks rather than dying in the CDR framing.
TEST(FuzzPointCloud2Seeds, AreCdrPointCloud2s) {
  std::size_t seeds = 0;
  for (const fs::path& file : inputs_of("pointcloud2")) {
    if (file.parent_path().parent_path().filename() != "corpus") continue;
    SCOPED_TRACE(file.string());
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
    std::copy(bytes.begin(), bytes.end(), payload.data);
    payload.length = static_cast<std::uint32_t>(bytes.size());
    sensor_msgs::msg::PointCloud2 cloud;
    EXPECT_TRUE(sensor_msgs::msg::PointCloud2PubSubType().deserialize(&payload, &cloud));
    EXPECT_EQ(cloud.header().frame_id(), "camera");
    ++seeds;
  }
  EXPECT_GE(seeds, 10u);
}

}  // namespace
}  // namespace cloudshape::fuzz
