// The ROS 2 side of the services: which sensor_msgs/PointCloud2 topics ingest reads, where the
// solver publishes Detection3DArray and MarkerArray, and how the markers look (config/pipeline.yaml "ros2").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cloudshape::config {

// Topic names are ROS 2 names ("/camera/depth/points"); on DDS they get the "rt" prefix.
struct Ros2Config {
  std::vector<std::string> input_topics;                  // PointCloud2 topics ingest reads (and each --ros-topic)
  std::string detections_topic = "/cloudshape/detections";  // vision_msgs/Detection3DArray; "" publishes none
  std::string markers_topic = "/cloudshape/markers";        // visualization_msgs/MarkerArray; "" publishes none
  // Results of clouds that came without a ROS header (files through cloudshape-inject) are
  // stamped with their injection time in this frame: RViz drops markers with no frame.
  std::string file_frame_id = "cloudshape";
  double marker_alpha = 0.6;          // opacity of the solid markers: the cloud stays visible through them
  double extent_line_width = 0.01;    // lines of an unknown object's extent, as a share of its largest size
  double label_height = 0.15;         // label text height, as a share of the object's largest size
  double label_fallback_height = 0.1; // ... of an object without a size (unknown, an error), in the cloud's unit
  std::int64_t circle_segments = 32;  // segments of the circles of a cone's or frustum's TRIANGLE_LIST
};

}  // namespace cloudshape::config
