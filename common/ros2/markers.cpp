// A cloud's recognition result as visualization_msgs/MarkerArray: solids and labels.
#include "ros2/markers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "ros2/messages.hpp"
#include "ros2/solid_view.hpp"

namespace cloudshape::ros2 {
namespace {

namespace mc = visualization_msgs::msg::Marker_Constants;

struct Rgb {
  float r, g, b;
};

// One colour per shape, the same in every display, so a shape is told at a glance.
Rgb shape_colour(const std::string& shape) {
  static const std::map<std::string, Rgb> colours = {
      {"box", {0.95f, 0.55f, 0.15f}},       {"tetrahedron", {0.65f, 0.35f, 0.85f}},
      {"pentagonal_prism", {0.2f, 0.75f, 0.7f}}, {"prism", {0.2f, 0.75f, 0.7f}},
      {"cone", {0.95f, 0.85f, 0.2f}},       {"frustum", {0.95f, 0.85f, 0.2f}},
      {"cylinder", {0.25f, 0.5f, 0.95f}},   {"sphere", {0.3f, 0.8f, 0.3f}}};
  const auto it = colours.find(shape);
  return it != colours.end() ? it->second : Rgb{0.6f, 0.6f, 0.6f};
}

std_msgs::msg::ColorRGBA colour(const Rgb& rgb, double alpha) {
  std_msgs::msg::ColorRGBA c;
  c.r(rgb.r);
  c.g(rgb.g);
  c.b(rgb.b);
  c.a(static_cast<float>(std::clamp(alpha, 0.0, 1.0)));
  return c;
}

visualization_msgs::msg::Marker base_marker(const std_msgs::msg::Header& header, const std::string& ns,
                                            std::int32_t id, std::int32_t type) {
  visualization_msgs::msg::Marker m;
  m.header(header);
  m.ns(ns);
  m.id(id);
  m.type(type);
  m.action(mc::ADD);
  m.pose().orientation().w(1.0);
  m.scale(to_vector3(Eigen::Vector3d::Ones()));
  return m;
}

std::int32_t marker_type(Primitive p) {
  switch (p) {
    case Primitive::cube: return mc::CUBE;
    case Primitive::sphere: return mc::SPHERE;
    case Primitive::cylinder: return mc::CYLINDER;
    case Primitive::triangles: break;
  }
  return mc::TRIANGLE_LIST;
}

visualization_msgs::msg::Marker solid_marker(const SolidView& view, const pipeline::ObjectResult& object,
                                             const std_msgs::msg::Header& header, const std::string& ns,
                                             std::int32_t id, const config::Ros2Config& style) {
  visualization_msgs::msg::Marker m = base_marker(header, ns, id, marker_type(view.primitive));
  m.pose(to_pose(view.marker_frame));
  m.scale(to_vector3(view.scale));
  m.color(colour(shape_colour(object.shape), style.marker_alpha));
  m.points().reserve(view.triangles.size());
  for (const Eigen::Vector3d& v : view.triangles) m.points().push_back(to_point(v));
  return m;
}

// The twelve edges of an object's extent, for an object without a solid: where the unknown thing is.
visualization_msgs::msg::Marker extent_marker(const OrientedBox& box, const std_msgs::msg::Header& header,
                                              const std::string& ns, std::int32_t id, const config::Ros2Config& style) {
  visualization_msgs::msg::Marker m = base_marker(header, ns, id, mc::LINE_LIST);
  m.pose(to_pose(box.frame));
  m.scale().x(style.extent_line_width * box.size.maxCoeff());  // RViz: a line's width is scale.x
  m.color(colour(shape_colour("unknown"), 1.0));
  const Eigen::Vector3d half = 0.5 * box.size;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (const double sa : {-1.0, 1.0}) {
      for (const double sb : {-1.0, 1.0}) {
        Eigen::Vector3d from = Eigen::Vector3d::Zero();
        from[a] = sa * half[a];
        from[b] = sb * half[b];
        Eigen::Vector3d to = from;
        from[axis] = -half[axis];
        to[axis] = half[axis];
        m.points().push_back(to_point(from));
        m.points().push_back(to_point(to));
      }
    }
  }
  return m;
}

// Where an object is drawn: its solid's box, else its extent, else nothing.
std::optional<OrientedBox> drawn_box(const std::optional<SolidView>& view, const pipeline::ObjectResult& object) {
  return view ? std::optional<OrientedBox>(view->box) : extent_box(object);
}

visualization_msgs::msg::Marker label_marker(const std::optional<OrientedBox>& box, const pipeline::ObjectResult& object,
                                             const std_msgs::msg::Header& header, const std::string& ns,
                                             std::int32_t id, const config::Ros2Config& style) {
  visualization_msgs::msg::Marker m = base_marker(header, ns, id, mc::TEXT_VIEW_FACING);
  const Eigen::Vector3d at = box ? box->frame.origin : object.center;
  m.pose().position(to_point(at.allFinite() ? at : Eigen::Vector3d::Zero()));
  const double size = box ? box->size.maxCoeff() : 0.0;
  const double height = size > 0.0 ? style.label_height * size : style.label_fallback_height;
  m.scale().z(height);  // RViz sizes text by scale.z alone
  m.color(colour({1.0f, 1.0f, 1.0f}, 1.0));
  m.text(object_label(object));
  return m;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

std::string object_label(const pipeline::ObjectResult& object) {
  std::string text = object.shape;
  if (object.partial) text = "partial " + text;
  for (const auto& [name, value] : object.dimensions) text += " " + name + " " + number(value);
  if (!object.reason.empty()) text += ": " + object.reason;
  if (object.shape != "unknown") text += " (" + number(100.0 * object.confidence) + "%)";
  return text;
}

visualization_msgs::msg::MarkerArray to_marker_array(const pipeline::RecognitionResult& result,
                                                     const io::RosHeader& header,
                                                     const config::Ros2Config& style) {
  const std_msgs::msg::Header h = to_msg(header);
  visualization_msgs::msg::MarkerArray out;
  visualization_msgs::msg::Marker clear = base_marker(h, result.source, 0, mc::CUBE);
  clear.action(mc::DELETEALL);
  out.markers().push_back(std::move(clear));
  const int segments = static_cast<int>(std::clamp<std::int64_t>(style.circle_segments, 3, 4096));
  for (std::size_t i = 0; i < result.objects.size(); ++i) {
    const pipeline::ObjectResult& object = result.objects[i];
    const auto id = static_cast<std::int32_t>(2 * i);
    const std::optional<SolidView> view = solid_view(object, segments);
    const std::optional<OrientedBox> box = drawn_box(view, object);
    if (view) {
      out.markers().push_back(solid_marker(*view, object, h, result.source, id, style));
    } else if (box) {
      out.markers().push_back(extent_marker(*box, h, result.source, id, style));
    }
    out.markers().push_back(label_marker(box, object, h, result.source, id + 1, style));
  }
  return out;
}

}  // namespace cloudshape::ros2
