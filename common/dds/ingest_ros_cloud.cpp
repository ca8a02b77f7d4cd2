// What cloudshape-ingest does with one received sensor_msgs/PointCloud2: decode, check, ingest.
#include "dds/ingest_ros_cloud.hpp"

#include "io/read_error.hpp"

namespace cloudshape::dds {

std::uint64_t ros_cloud_id(const std::array<std::uint8_t, 16>& writer_guid, std::int64_t sequence_number) {
  // FNV-1a over the identity, then a splitmix64 finaliser: ids spread evenly over the lanes.
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto mix = [&h](std::uint8_t byte) {
    h ^= byte;
    h *= 0x100000001b3ULL;
  };
  for (std::uint8_t b : writer_guid) mix(b);
  for (int i = 0; i < 8; ++i) mix(static_cast<std::uint8_t>(static_cast<std::uint64_t>(sequence_number) >> (8 * i)));
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ULL;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebULL;
  h ^= h >> 31;
  return h == 0 ? 1 : h;
}

msg::CloudHeader ros_cloud_header(const std::string& ros_topic, const io::RosHeader& header,
                                  std::uint64_t cloud_id, std::int64_t source_time_ns) {
  msg::CloudHeader out;
  out.cloud_id(cloud_id);
  out.source(ros_topic);
  out.inject_time_ns(source_time_ns);
  out.sensor().stamp_sec(header.stamp.sec);
  out.sensor().stamp_nanosec(header.stamp.nanosec);
  out.sensor().frame_id(header.frame_id);
  return out;
}

RawCloudPoints pointcloud2_points(const io::PointCloud2& cloud, const config::InputConfig& limits) {
  io::CloudFile decoded;
  try {
    io::ReadLimits read_limits;
    read_limits.max_points = static_cast<std::size_t>(limits.max_points);
    read_limits.max_bytes = static_cast<std::size_t>(limits.max_bytes);
    decoded = io::decode_pointcloud2(cloud, "PointCloud2", read_limits);
  } catch (const io::ReadError& e) {
    // The topic is the cloud's source already: the reason names the place and the problem.
    throw RawCloudError(e.place() + ": " + e.problem());
  }
  const std::size_t count = std::size_t{cloud.width} * cloud.height;
  if (count == 0) {
    throw RawCloudError("no points (width x height = " + std::to_string(cloud.width) + " x " +
                        std::to_string(cloud.height) + ")");
  }
  RawCloudPoints out;
  out.points = std::move(decoded.points);
  out.grid = std::move(decoded.grid);
  out.non_finite_dropped = decoded.non_finite_dropped;
  check_usable_points(out, count, limits);
  return out;
}

std::vector<msg::FilteredCloud> ingest_pointcloud2(const msg::CloudHeader& header, const io::PointCloud2& cloud,
                                                   const config::PipelineConfig& cfg, parallel::ThreadPool* pool) {
  return filtered_clouds(header, pointcloud2_points(cloud, cfg.input), cfg, pool);
}

}  // namespace cloudshape::dds
