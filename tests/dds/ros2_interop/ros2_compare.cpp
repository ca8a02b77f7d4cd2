// The acceptance check of the ROS 2 tests: received ROS 2 results against recognize's.
#include "ros2_compare.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "config/ros2_config.hpp"
#include "ros2/detections.hpp"
#include "ros2/markers.hpp"

namespace cloudshape::testing {
namespace {

using nlohmann::json;

json header_json(const std_msgs::msg::Header& h) {
  return {{"sec", h.stamp().sec()}, {"nanosec", h.stamp().nanosec()}, {"frame_id", h.frame_id()}};
}

json pose_json(const geometry_msgs::msg::Pose& p) {
  return {{"position", {p.position().x(), p.position().y(), p.position().z()}},
          {"orientation", {p.orientation().x(), p.orientation().y(), p.orientation().z(), p.orientation().w()}}};
}

Eigen::Matrix3d rotation(const json& q) {
  return Eigen::Quaterniond(q[3].get<double>(), q[0].get<double>(), q[1].get<double>(), q[2].get<double>())
      .normalized()
      .toRotationMatrix();
}

// Orientations: each column of the rotation equal up to its sign.
std::string orientation_difference(const json& actual, const json& expected, const std::string& at) {
  const Eigen::Matrix3d a = rotation(actual), e = rotation(expected);
  for (int c = 0; c < 3; ++c) {
    if ((a.col(c) - e.col(c)).norm() > 1e-9 && (a.col(c) + e.col(c)).norm() > 1e-9) {
      return at + ": axis " + std::to_string(c) + " differs: " + actual.dump() + " vs " + expected.dump();
    }
  }
  return {};
}

std::string difference(const json& actual, const json& expected, const std::string& at) {
  if (expected.is_number_float() || (expected.is_number() && actual.is_number_float())) {
    if (!actual.is_number()) return at + ": not a number: " + actual.dump();
    const double a = actual.get<double>(), e = expected.get<double>();
    if (std::abs(a - e) > 1e-9 * std::max(1.0, std::abs(e))) {
      return at + ": " + actual.dump() + " vs " + expected.dump();
    }
    return {};
  }
  if (expected.is_object()) {
    if (!actual.is_object() || actual.size() != expected.size()) return at + ": " + actual.dump() + " vs " + expected.dump();
    for (const auto& [key, value] : expected.items()) {
      if (!actual.contains(key)) return at + ": no " + key;
      const std::string d = key == "orientation" ? orientation_difference(actual[key], value, at + "." + key)
                                                 : difference(actual[key], value, at + "." + key);
      if (!d.empty()) return d;
    }
    return {};
  }
  if (expected.is_array()) {
    if (!actual.is_array() || actual.size() != expected.size()) {
      return at + ": " + std::to_string(actual.size()) + " entries, expected " + std::to_string(expected.size()) +
             ": " + actual.dump().substr(0, 400);
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const std::string d = difference(actual[i], expected[i], at + "[" + std::to_string(i) + "]");
      if (!d.empty()) return d;
    }
    return {};
  }
  return actual == expected ? std::string() : at + ": " + actual.dump() + " vs " + expected.dump();
}

}  // namespace

json detections_json(const vision_msgs::msg::Detection3DArray& a) {
  json out = {{"header", header_json(a.header())}, {"detections", json::array()}};
  for (const vision_msgs::msg::Detection3D& d : a.detections()) {
    json j = {{"header", header_json(d.header())},
              {"id", d.id()},
              {"results", json::array()},
              {"bbox",
               {{"center", pose_json(d.bbox().center())},
                {"size", {d.bbox().size().x(), d.bbox().size().y(), d.bbox().size().z()}}}}};
    for (const auto& h : d.results()) {
      j["results"].push_back({{"class_id", h.hypothesis().class_id()},
                              {"score", h.hypothesis().score()},
                              {"pose", pose_json(h.pose().pose())}});
    }
    out["detections"].push_back(j);
  }
  return out;
}

json markers_json(const visualization_msgs::msg::MarkerArray& a) {
  json out = json::array();
  for (const visualization_msgs::msg::Marker& m : a.markers()) {
    out.push_back({{"header", header_json(m.header())},
                   {"ns", m.ns()},
                   {"id", m.id()},
                   {"type", m.type()},
                   {"action", m.action()},
                   {"pose", pose_json(m.pose())},
                   {"scale", {m.scale().x(), m.scale().y(), m.scale().z()}},
                   {"alpha", m.color().a()},
                   {"points", m.points().size()},
                   {"text", m.text()}});
  }
  return out;
}

std::string ros_results_difference(const json& detections, const json& markers,
                                   const pipeline::RecognitionResult& expected, const io::RosHeader& header) {
  const std::string d = difference(detections, detections_json(ros2::to_detection_array(expected, header)),
                                   "detections");
  if (!d.empty()) return d;
  return difference(markers, markers_json(ros2::to_marker_array(expected, header, config::Ros2Config{})), "markers");
}

}  // namespace cloudshape::testing
