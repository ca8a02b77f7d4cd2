// One input of each fuzz target through the code under test, shared by the libFuzzer targets
// and by the regression test that replays every stored input in the default build.
#pragma once

#include <string>
#include <string_view>

#include "io/cloud_file.hpp"

namespace cloudshape::fuzz {

// Small enough that a lying header cannot make the fuzzer run out of memory.
inline io::ReadLimits fuzz_limits() {
  io::ReadLimits limits;
  limits.max_points = 100'000;
  limits.max_bytes = 1u << 20;
  return limits;
}

// Each returns "" when the input was read or refused the documented way (io::ReadError for
// files, dds::RawCloudError for a raw-cloud or PointCloud2 sample), else the invariant the result broke.
// Any other exception escapes: for the fuzzer that is a finding like a crash.
std::string check_pcd_input(std::string_view bytes);
std::string check_ply_input(std::string_view bytes);  // as a point cloud and as a mesh
std::string check_xyz_input(std::string_view bytes);
// An MCAP recording: read, rewritten by McapWriter and read again, its PointCloud2 messages decoded.
std::string check_mcap_input(std::string_view bytes);
// `bytes` is a CDR-encoded cloudshape::msg::RawCloud as it arrives on the raw-cloud topic.
std::string check_raw_cloud_sample(std::string_view bytes);
// `bytes` is a CDR-encoded sensor_msgs/PointCloud2 as it arrives on a ROS 2 topic ingest reads:
// its layout decoded (io::decode_pointcloud2) and checked, then ingested.
std::string check_pointcloud2_sample(std::string_view bytes);

}  // namespace cloudshape::fuzz
