// cloudshape-echo --record: every result it prints also goes to an MCAP recording, and with
// --record-clouds the input cloud it belongs to (taken from the raw-cloud topic) too.
#include "recording.hpp"

#include "dds/convert.hpp"
#include "io/pointcloud2_encode.hpp"

namespace cloudshape::echo {
namespace {

constexpr std::size_t kMaxWaitingClouds = 256;

}  // namespace

EchoRecording::EchoRecording(const std::string& path, recording::RecorderSettings settings)
    : settings_(settings), recorder_(path, std::move(settings)) {}

void EchoRecording::add_cloud(msg::RawCloud&& cloud) {
  if (!settings_.clouds) return;
  auto key = std::make_pair(cloud.header().cloud_id(), cloud.header().source());
  clouds_[std::move(key)] = std::move(cloud);
  // Cloud ids count up: the smallest key is the one waiting longest.
  if (clouds_.size() > kMaxWaitingClouds) clouds_.erase(clouds_.begin());
}

void EchoRecording::record(const pipeline::RecognitionResult& result, const msg::CloudHeader& header) {
  const auto inject_time = static_cast<std::uint64_t>(header.inject_time_ns());
  const io::RosHeader ros_header = recording::file_header(inject_time, settings_.ros2);
  const auto cloud = clouds_.find({header.cloud_id(), header.source()});
  if (cloud == clouds_.end()) {
    if (settings_.clouds) ++clouds_missed_;
    recorder_.record(result, ros_header, inject_time);
    return;
  }
  GridLayout grid;
  if (cloud->second.height() > 1) {
    grid.width = cloud->second.width();
    grid.height = cloud->second.height();
    grid.pixel = cloud->second.pixel();
  }
  const io::PointCloud2 message =
      io::encode_pointcloud2(dds::from_xyz(cloud->second.xyz()), grid, {}, ros_header);
  recorder_.record(result, ros_header, inject_time, &message);
  clouds_.erase(cloud);
}

}  // namespace cloudshape::echo
