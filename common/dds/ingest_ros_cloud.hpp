// What cloudshape-ingest does with one received sensor_msgs/PointCloud2, without DDS: the cloud's
// header (id, topic, ROS 2 header), the layout decoded and checked, then ingest as for a raw cloud.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cloudshape.h"
#include "config/pipeline_config.hpp"
#include "dds/ingest_sample.hpp"
#include "io/pointcloud2.hpp"

namespace cloudshape::dds {

// A ROS 2 cloud's id, from its sample's identity (the writer's 16-byte GUID and the sequence
// number): the same in every ingest replica, so they split the clouds (cloud_id % lanes) as they
// split injected ones, and different for every sample. Never 0 (0 stands for an unknown cloud).
std::uint64_t ros_cloud_id(const std::array<std::uint8_t, 16>& writer_guid, std::int64_t sequence_number);

// The header a PointCloud2 travels with: `cloud_id`, source = the ROS 2 topic, inject_time_ns =
// when its publisher wrote it (the sample's source timestamp), sensor = its std_msgs/Header.
msg::CloudHeader ros_cloud_header(const std::string& ros_topic, const io::RosHeader& header,
                                  std::uint64_t cloud_id, std::int64_t source_time_ns);

// The finite points of `cloud` with its grid. Throws RawCloudError naming the problem for a bad
// layout (io::decode_pointcloud2, within input.max_points and input.max_bytes: "fields: no field
// named 'z' (fields: x, y, rgb)"), a cloud of no point, or one check_usable_points refuses.
RawCloudPoints pointcloud2_points(const io::PointCloud2& cloud, const config::InputConfig& limits);

// pointcloud2_points, then filtered_clouds with `header`.
std::vector<msg::FilteredCloud> ingest_pointcloud2(const msg::CloudHeader& header, const io::PointCloud2& cloud,
                                                   const config::PipelineConfig& cfg,
                                                   parallel::ThreadPool* pool = nullptr);

}  // namespace cloudshape::dds
