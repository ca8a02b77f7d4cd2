// The ingest fuzz checks: the bytes are a raw-cloud or PointCloud2 sample as the ingest DataReader
// deserializes it (CDR with encapsulation, the checked type), then the very functions the service calls.
#include <cmath>
#include <fastdds/rtps/common/SerializedPayload.h>

#include "dds/checked_type.hpp"
#include "dds/ingest_ros_cloud.hpp"
#include "dds/ingest_sample.hpp"
#include "dds/ros2_topics.hpp"
#include "dds/topics.hpp"
#include "ros2/messages.hpp"
#include "fuzz_checks.hpp"

namespace cloudshape::fuzz {
namespace {

std::string filtered_problems(const std::vector<msg::FilteredCloud>& out, std::size_t points_sent) {
  if (out.empty()) return "no filtered cloud for a raw cloud";
  const std::uint32_t count = out.front().header().object_count();
  if (count == 0 ? out.size() != 1 : out.size() != count) return "object_count disagrees with the messages";
  for (std::size_t i = 0; i < out.size(); ++i) {
    const msg::FilteredCloud& o = out[i];
    if (o.header().error()) return "a processed cloud is marked failed";
    if (o.header().object_index() != i || o.header().object_count() != count) return "object numbering broken";
    if (o.cloud().xyz().size() % 3 != 0) return "filtered xyz is not whole triples";
    if (o.cloud().points_in() > points_sent) return "more points in than were sent";
    for (double v : o.cloud().xyz()) {
      if (!std::isfinite(v)) return "a non-finite filtered coordinate";
    }
    if (!std::isfinite(o.cloud().resolution()) || o.cloud().resolution() < 0) return "resolution not finite";
  }
  return {};
}

// The points of a decoded PointCloud2 against its layout: every pixel is a kept point or a
// dropped one, kept points are finite and within the limit, an organized grid is well formed.
std::string decoded_problems(const io::PointCloud2& cloud, const dds::RawCloudPoints& points,
                             const config::InputConfig& limits) {
  const std::size_t pixels = std::size_t{cloud.width} * cloud.height;
  if (points.points.size() + points.non_finite_dropped != pixels) return "kept + dropped points != width * height";
  for (const Point& p : points.points) {
    if (!p.allFinite()) return "a non-finite point kept";
    if (p.cwiseAbs().maxCoeff() > limits.max_coordinate) return "a point beyond max_coordinate kept";
  }
  if (cloud.height > 1) {
    if (points.grid.width != cloud.width || points.grid.height != cloud.height) return "grid size not the layout's";
    if (points.grid.pixel.size() != points.points.size()) return "a pixel count other than the point count";
    for (std::size_t i = 0; i < points.grid.pixel.size(); ++i) {
      if (points.grid.pixel[i] >= pixels) return "a pixel outside the grid";
      if (i > 0 && points.grid.pixel[i] <= points.grid.pixel[i - 1]) return "pixels not increasing";
    }
  } else if (!points.grid.pixel.empty()) {
    return "pixels for an unorganized cloud";
  }
  return {};
}

}  // namespace

std::string check_pointcloud2_sample(std::string_view bytes) {
  // The type ingest registers for a ROS 2 topic (dds::Participant::topic of PointCloud2Topic).
  dds::CheckedPubSubType<dds::PointCloud2Topic> type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  dds::RosCloudSample sample;
  if (!type.deserialize(&payload, &sample)) return "a PointCloud2 sample is not delivered";
  if (!sample.undecodable.empty()) return {};  // ingest refuses it (ros_cloud_input.cpp)
  const io::PointCloud2 cloud = ros2::from_msg(std::move(sample.cloud));
  config::PipelineConfig cfg;
  cfg.input.max_points = 20'000;  // keeps one fuzz input to milliseconds
  dds::RawCloudPoints points;
  try {
    points = dds::pointcloud2_points(cloud, cfg.input);
  } catch (const dds::RawCloudError&) {
    return {};
  }
  const std::string problem = decoded_problems(cloud, points, cfg.input);
  if (!problem.empty()) return problem;
  const msg::CloudHeader header = dds::ros_cloud_header("/fuzz", cloud.header, 1, 0);
  return filtered_problems(dds::filtered_clouds(header, points, cfg), points.points.size() + points.non_finite_dropped);
}

std::string check_raw_cloud_sample(std::string_view bytes) {
  // The type the services register (dds::Participant::topic), not the bare generated one.
  dds::CheckedPubSubType<decltype(dds::topics::raw_cloud)> type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  msg::RawCloud cloud;
  if (!type.deserialize(&payload, &cloud)) return "a raw-cloud sample is not delivered";
  // Whether the bytes decode at all, by the bare generated type (which may throw).
  bool decodes = false;
  try {
    msg::RawCloud bare_cloud;
    decodes = msg::RawCloudPubSubType().deserialize(&payload, &bare_cloud);
  } catch (const eprosima::fastcdr::exception::Exception&) {
  }
  if (!decodes && !cloud.header().error()) return "an undecodable sample is not marked failed";

  // As service::run does: a failed sample is passed on, anything else goes to the stage.
  std::string refusal;
  if (cloud.header().error()) {
    refusal = cloud.header().error_text();
  } else {
    config::PipelineConfig cfg;
    cfg.input.max_points = 20'000;  // keeps one fuzz input to milliseconds
    try {
      return filtered_problems(dds::ingest_raw_cloud(cloud, cfg), cloud.xyz().size() / 3);
    } catch (const dds::RawCloudError& e) {
      refusal = e.what();
    }
  }
  const msg::FilteredCloud refused = dds::refused_raw_cloud(cloud, "ingest", refusal);
  if (!refused.header().error() || refused.header().object_count() != 1) return "a refusal is not one failed object";
  return {};
}

}  // namespace cloudshape::fuzz
