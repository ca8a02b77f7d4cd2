// The ROS 2 messages of one cloud's joined result: Detection3DArray and MarkerArray.
#include "dds/ros2_results.hpp"

#include "dds/convert.hpp"
#include "ros2/detections.hpp"
#include "ros2/markers.hpp"

namespace cloudshape::dds {

io::RosHeader ros_result_header(const msg::CloudHeader& header, const config::Ros2Config& cfg) {
  const msg::SensorHeader& s = header.sensor();
  if (!s.frame_id().empty()) return {{s.stamp_sec(), s.stamp_nanosec()}, s.frame_id()};
  const std::int64_t ns = header.inject_time_ns();
  constexpr std::int64_t kBillion = 1'000'000'000;
  // A floor division, so an (odd) negative time still gives nanoseconds in 0..1e9.
  std::int64_t sec = ns / kBillion, nsec = ns % kBillion;
  if (nsec < 0) {
    nsec += kBillion;
    --sec;
  }
  return {{static_cast<std::int32_t>(sec), static_cast<std::uint32_t>(nsec)}, cfg.file_frame_id};
}

RosResults ros_results(const std::vector<msg::ShapeResult>& objects, const config::Ros2Config& cfg) {
  const pipeline::RecognitionResult result = to_recognition_result(objects);
  const io::RosHeader header =
      objects.empty() ? io::RosHeader{{0, 0}, cfg.file_frame_id} : ros_result_header(objects.front().header(), cfg);
  return {ros2::to_detection_array(result, header), ros2::to_marker_array(result, header, cfg)};
}

}  // namespace cloudshape::dds
