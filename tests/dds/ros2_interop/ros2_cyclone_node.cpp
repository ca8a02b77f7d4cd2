// cloudshape from Cyclone DDS as a ROS 2 node sees it, without ROS: publishes point clouds as
// sensor_msgs/PointCloud2 (ROS 2 sensor-data QoS) and prints what comes back on
// rt/cloudshape/detections and rt/cloudshape/markers, one JSON line per frame.
//
//   ros2_cyclone_node [--domain N] [--topic /camera/points] [--frame-id F] [--timeout S] FRAME...
//   FRAME: FILE:float32 or FILE:float64. FILE: "width height", then width * height lines
//   "x y z", row by row ("nan nan nan" where a pixel has no point; height 1: unorganized).
// Types: idlc from ros2_messages.idl. Loopback: CYCLONEDDS_URI=file://.../cyclonedds_localhost.xml.
#include <dds/dds.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "ros2_messages.h"  // idlc's C types

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

struct Frame {
  std::uint32_t width = 0, height = 0;
  std::vector<double> xyz;  // width * height points, NaN where none
  bool f64 = false;
};

Frame read_frame(const std::string& arg) {
  const std::size_t colon = arg.rfind(':');
  if (colon == std::string::npos) throw std::runtime_error(arg + ": expected FILE:float32 or FILE:float64");
  Frame f;
  const std::string type = arg.substr(colon + 1);
  if (type != "float32" && type != "float64") throw std::runtime_error(arg + ": type must be float32 or float64");
  f.f64 = type == "float64";
  std::ifstream in(arg.substr(0, colon));
  if (!(in >> f.width >> f.height)) throw std::runtime_error(arg + ": cannot read 'width height'");
  std::string token;
  while (in >> token) f.xyz.push_back(std::strtod(token.c_str(), nullptr));  // strtod reads "nan"
  if (f.xyz.size() != 3ull * f.width * f.height) throw std::runtime_error(arg + ": not width * height points");
  return f;
}

// A depth camera's layout: x y z (float32 or float64), then a packed float32 rgb, little-endian.
sensor_msgs_msg_dds__PointCloud2_ to_pointcloud2(const Frame& f, const char* frame_id, int index) {
  const std::uint32_t size = f.f64 ? 8 : 4, step = f.f64 ? 32 : 16;
  static const char* names[4] = {"x", "y", "z", "rgb"};
  sensor_msgs_msg_dds__PointCloud2_ m{};
  m.header.stamp.sec = 1000 + index;
  m.header.stamp.nanosec = 1000u * static_cast<std::uint32_t>(index) + 7u;
  m.header.frame_id = const_cast<char*>(frame_id);
  m.height = f.height;
  m.width = f.width;
  m.fields._length = m.fields._maximum = 4;
  m.fields._buffer = dds_sequence_sensor_msgs_msg_dds__PointField__allocbuf(4);
  for (std::uint32_t i = 0; i < 4; ++i) {
    m.fields._buffer[i].name = const_cast<char*>(names[i]);
    m.fields._buffer[i].offset = i * size;
    m.fields._buffer[i].datatype = (i < 3 && f.f64) ? 8 : 7;  // FLOAT64, FLOAT32
    m.fields._buffer[i].count = 1;
  }
  m.is_bigendian = false;
  m.point_step = step;
  m.row_step = step * f.width;
  m.data._length = m.data._maximum = m.row_step * f.height;
  m.data._buffer = static_cast<std::uint8_t*>(std::calloc(m.data._length, 1));
  for (std::size_t p = 0; p < std::size_t{f.width} * f.height; ++p) {
    std::uint8_t* at = m.data._buffer + p * step;
    for (int a = 0; a < 3; ++a) {
      if (f.f64) {
        std::memcpy(at + a * size, &f.xyz[3 * p + a], 8);
      } else {
        const float v = static_cast<float>(f.xyz[3 * p + a]);
        std::memcpy(at + a * size, &v, 4);
      }
    }
    const std::uint32_t grey = 0x808080;
    std::memcpy(at + 3 * size, &grey, 4);
  }
  m.is_dense = false;
  return m;
}

json header_json(const std_msgs_msg_dds__Header_& h) {
  return {{"sec", h.stamp.sec}, {"nanosec", h.stamp.nanosec}, {"frame_id", h.frame_id}};
}

json pose_json(const geometry_msgs_msg_dds__Pose_& p) {
  return {{"position", {p.position.x, p.position.y, p.position.z}},
          {"orientation", {p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w}}};
}

json detections_json(const vision_msgs_msg_dds__Detection3DArray_& a) {
  json out = {{"header", header_json(a.header)}, {"detections", json::array()}};
  for (std::uint32_t i = 0; i < a.detections._length; ++i) {
    const vision_msgs_msg_dds__Detection3D_& d = a.detections._buffer[i];
    json j = {{"header", header_json(d.header)}, {"id", d.id}, {"results", json::array()},
              {"bbox", {{"center", pose_json(d.bbox.center)}, {"size", {d.bbox.size.x, d.bbox.size.y, d.bbox.size.z}}}}};
    for (std::uint32_t r = 0; r < d.results._length; ++r) {
      const auto& h = d.results._buffer[r];
      j["results"].push_back({{"class_id", h.hypothesis.class_id}, {"score", h.hypothesis.score},
                              {"pose", pose_json(h.pose.pose)}});
    }
    out["detections"].push_back(j);
  }
  return out;
}

json markers_json(const visualization_msgs_msg_dds__MarkerArray_& a) {
  json out = json::array();
  for (std::uint32_t i = 0; i < a.markers._length; ++i) {
    const visualization_msgs_msg_dds__Marker_& m = a.markers._buffer[i];
    out.push_back({{"header", header_json(m.header)}, {"ns", m.ns}, {"id", m.id}, {"type", m.type},
                   {"action", m.action}, {"pose", pose_json(m.pose)}, {"scale", {m.scale.x, m.scale.y, m.scale.z}},
                   {"alpha", m.color.a}, {"points", m.points._length}, {"text", m.text}});
  }
  return out;
}

// Takes every waiting sample of `reader`; `use` gets each valid one.
template <class Sample, class Use>
void take_all(dds_entity_t reader, Use use) {
  void* samples[1] = {nullptr};
  dds_sample_info_t info[1];
  while (dds_take(reader, samples, info, 1, 1) > 0) {  // loans the sample
    if (info[0].valid_data) use(*static_cast<const Sample*>(samples[0]));
    dds_return_loan(reader, samples, 1);
  }
}

bool same_stamp(const std_msgs_msg_dds__Header_& h, const sensor_msgs_msg_dds__PointCloud2_& cloud) {
  return h.stamp.sec == cloud.header.stamp.sec && h.stamp.nanosec == cloud.header.stamp.nanosec;
}

}  // namespace

int main(int argc, char** argv) {
  int domain = 0;
  double timeout_s = 120;
  std::string topic = "/camera/points", frame_id = "camera";
  std::vector<Frame> frames;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      const bool has_value = i + 1 < argc;
      if (a == "--domain" && has_value) domain = std::atoi(argv[++i]);
      else if (a == "--topic" && has_value) topic = argv[++i];
      else if (a == "--frame-id" && has_value) frame_id = argv[++i];
      else if (a == "--timeout" && has_value) timeout_s = std::atof(argv[++i]);
      else frames.push_back(read_frame(a));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ros2_cyclone_node: %s\n", e.what());
    return 2;
  }

  const dds_entity_t participant = dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
  if (participant < 0) { std::fprintf(stderr, "cannot create participant: %s\n", dds_strretcode(-participant)); return 1; }
  // ROS 2 names on DDS: topic "rt" + name, types from module dds_ (ros2_messages.idl).
  const dds_entity_t cloud_topic = dds_create_topic(participant, &sensor_msgs_msg_dds__PointCloud2__desc,
                                                    ("rt" + topic).c_str(), nullptr, nullptr);
  const dds_entity_t detections_topic = dds_create_topic(participant, &vision_msgs_msg_dds__Detection3DArray__desc,
                                                         "rt/cloudshape/detections", nullptr, nullptr);
  const dds_entity_t markers_topic = dds_create_topic(participant, &visualization_msgs_msg_dds__MarkerArray__desc,
                                                      "rt/cloudshape/markers", nullptr, nullptr);
  // ROS 2's sensor-data profile for the cloud, its default profile for what we read.
  dds_qos_t* sensor = dds_create_qos();
  dds_qset_reliability(sensor, DDS_RELIABILITY_BEST_EFFORT, 0);
  dds_qset_history(sensor, DDS_HISTORY_KEEP_LAST, 5);
  dds_qset_durability(sensor, DDS_DURABILITY_VOLATILE);
  dds_qos_t* reliable = dds_create_qos();
  dds_qset_reliability(reliable, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_history(reliable, DDS_HISTORY_KEEP_LAST, 10);
  dds_qset_durability(reliable, DDS_DURABILITY_VOLATILE);
  const dds_entity_t writer = dds_create_writer(participant, cloud_topic, sensor, nullptr);
  const dds_entity_t detections = dds_create_reader(participant, detections_topic, reliable, nullptr);
  const dds_entity_t markers = dds_create_reader(participant, markers_topic, reliable, nullptr);
  dds_delete_qos(sensor);
  dds_delete_qos(reliable);
  if (writer < 0 || detections < 0 || markers < 0) { std::fprintf(stderr, "cannot create endpoints\n"); return 1; }

  // cloudshape-ingest reads the topic only once the whole chain listens: wait for it.
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_s);
  dds_publication_matched_status_t matched{};
  while (dds_get_publication_matched_status(writer, &matched) == DDS_RETCODE_OK && matched.current_count == 0) {
    if (Clock::now() > deadline) { std::fprintf(stderr, "no reader of rt%s\n", topic.c_str()); return 1; }
    dds_sleepfor(DDS_MSECS(50));
  }

  int status = 0;
  for (std::size_t i = 0; i < frames.size() && status == 0; ++i) {
    sensor_msgs_msg_dds__PointCloud2_ cloud = to_pointcloud2(frames[i], frame_id.c_str(), static_cast<int>(i));
    json got_detections, got_markers;
    auto sent = Clock::now() - std::chrono::hours(1);
    while (got_detections.is_null() || got_markers.is_null()) {
      if (Clock::now() > deadline) { std::fprintf(stderr, "frame %zu: no answer in time\n", i); status = 1; break; }
      // Best effort may lose a frame: send it again when no answer came for a while.
      if (Clock::now() - sent > std::chrono::seconds(10)) {
        if (dds_write(writer, &cloud) != DDS_RETCODE_OK) { std::fprintf(stderr, "write failed\n"); status = 1; break; }
        sent = Clock::now();
      }
      take_all<vision_msgs_msg_dds__Detection3DArray_>(detections, [&](const auto& a) {
        if (got_detections.is_null() && same_stamp(a.header, cloud)) got_detections = detections_json(a);
      });
      take_all<visualization_msgs_msg_dds__MarkerArray_>(markers, [&](const auto& a) {
        if (got_markers.is_null() && a.markers._length > 0 && same_stamp(a.markers._buffer[0].header, cloud)) {
          got_markers = markers_json(a);
        }
      });
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    std::free(cloud.data._buffer);
    dds_free(cloud.fields._buffer);
    if (status == 0) {
      std::printf("%s\n", json{{"frame", i}, {"detections", got_detections}, {"markers", got_markers}}.dump().c_str());
      std::fflush(stdout);
    }
  }
  dds_delete(participant);
  return status;
}
