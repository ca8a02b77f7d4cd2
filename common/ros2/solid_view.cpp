// What a recognised solid looks like to ROS 2: its own bounding box, from its dimensions, and the
// RViz marker that draws it. One function per shape; views() maps shape names to them.
#include "ros2/solid_view.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "ros2/detail/solid_meshes.hpp"

namespace cloudshape::ros2 {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

// The box around `vertices` (given in `frame`), along the frame's axes.
OrientedBox box_around(const Frame& frame, const detail::Triangles& vertices) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec3& v : vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  OrientedBox box;
  box.frame.rotation = frame.rotation;
  box.frame.origin = frame.origin + frame.rotation * (0.5 * (lo + hi));
  box.size = hi - lo;
  return box;
}

SolidView triangles_view(const Frame& frame, detail::Triangles triangles) {
  SolidView view;
  view.box = box_around(frame, triangles);
  view.marker_frame = frame;
  view.triangles = std::move(triangles);
  return view;
}

// Each function gets the object, its right-handed frame (origin: pose.center) and the circle
// segments; nullopt when a dimension it needs is missing or not positive.
using ViewFn = std::optional<SolidView> (*)(const pipeline::ObjectResult&, const Frame&, int);

std::optional<SolidView> box_view(const pipeline::ObjectResult& o, const Frame& f, int) {
  const Vec3 size(dimension(o, "length"), dimension(o, "width"), dimension(o, "height"));
  if (!positive(size.x()) || !positive(size.y()) || !positive(size.z())) return std::nullopt;
  SolidView view;
  view.box = {f, size};
  view.primitive = Primitive::cube;
  view.marker_frame = f;
  view.scale = size;
  return view;
}

std::optional<SolidView> sphere_view(const pipeline::ObjectResult& o, const Frame& f, int) {
  const double r = dimension(o, "radius");
  if (!positive(r)) return std::nullopt;
  SolidView view;
  view.box = {f, Vec3::Constant(2.0 * r)};
  view.primitive = Primitive::sphere;
  view.marker_frame = f;
  view.scale = Vec3::Constant(2.0 * r);
  return view;
}

std::optional<SolidView> cylinder_view(const pipeline::ObjectResult& o, const Frame& f, int) {
  const double r = dimension(o, "radius"), h = dimension(o, "height");
  if (!positive(r) || !positive(h)) return std::nullopt;
  SolidView view;
  view.box = {f, Vec3(h, 2.0 * r, 2.0 * r)};
  view.primitive = Primitive::cylinder;
  // RViz draws a cylinder along its z: the frame's axes turned y, z, x (still right-handed).
  view.marker_frame.origin = f.origin;
  view.marker_frame.rotation << f.rotation.col(1), f.rotation.col(2), f.rotation.col(0);
  view.scale = Vec3(2.0 * r, 2.0 * r, h);
  return view;
}

std::optional<SolidView> cone_view(const pipeline::ObjectResult& o, const Frame& f, int segments) {
  const double r = dimension(o, "radius"), h = dimension(o, "height");
  if (!positive(r) || !positive(h)) return std::nullopt;
  return triangles_view(f, detail::revolved(r, 0.0, h, segments));  // origin: the base centre
}

// A regular pentagon around the axis; pose.axes[1] is the outward normal of one side.
std::optional<SolidView> pentagonal_prism_view(const pipeline::ObjectResult& o, const Frame& f, int) {
  const double side = dimension(o, "side"), h = dimension(o, "height");
  if (!positive(side) || !positive(h)) return std::nullopt;
  const double circumradius = side / (2.0 * std::sin(kPi / 5.0));
  std::vector<Eigen::Vector2d> pentagon;
  for (int k = 0; k < 5; ++k) {
    const double t = kPi / 5.0 + 2.0 * kPi * k / 5.0;
    pentagon.emplace_back(circumradius * std::cos(t), circumradius * std::sin(t));
  }
  return triangles_view(f, detail::prism(pentagon, h));
}

// A truncated cone from its larger base (pose.center) along axis 0 to its smaller end.
std::optional<SolidView> frustum_view(const pipeline::ObjectResult& o, const Frame& f, int segments) {
  const double r = dimension(o, "radius"), top = dimension(o, "top_radius"), h = dimension(o, "height");
  if (!positive(r) || !positive(top) || !positive(h)) return std::nullopt;
  return triangles_view(f, detail::revolved(r, top, h, segments));
}

// A right prism of the object's polygon (u along axis 1, v along axis 2, about pose.center),
// extruded along axis 0.
std::optional<SolidView> prism_view(const pipeline::ObjectResult& o, const Frame& f, int) {
  const double h = dimension(o, "height");
  if (!positive(h) || o.polygon.size() < 3) return std::nullopt;
  for (const Eigen::Vector2d& v : o.polygon) {
    if (!v.allFinite()) return std::nullopt;
  }
  return triangles_view(f, detail::prism(o.polygon, h));
}

// The tetrahedron's own four corners when it has them; else the regular one of its mean edge:
// pose.axes[0] points from the centroid to vertex 0, axes[1] to vertex 1 (across axis 0).
std::optional<SolidView> tetrahedron_view(const pipeline::ObjectResult& o, const Frame& f, int) {
  if (o.vertices.size() == 4) {
    std::array<Vec3, 4> local;
    for (std::size_t k = 0; k < 4; ++k) {
      if (!o.vertices[k].allFinite()) return std::nullopt;
      local[k] = f.rotation.transpose() * (o.vertices[k] - f.origin);
    }
    return triangles_view(f, detail::tetrahedron(local));
  }
  const double edge = dimension(o, "edge");
  if (!positive(edge)) return std::nullopt;
  const double r = edge * std::sqrt(6.0) / 4.0;       // centroid to vertex
  const double ring = r * 2.0 * std::sqrt(2.0) / 3.0;  // the other three around axis 0
  std::array<Vec3, 4> vertices;
  vertices[0] = Vec3(r, 0, 0);
  for (int k = 0; k < 3; ++k) {
    const double t = 2.0 * kPi * k / 3.0;
    vertices[k + 1] = Vec3(-r / 3.0, ring * std::cos(t), ring * std::sin(t));
  }
  return triangles_view(f, detail::tetrahedron(vertices));
}

const std::map<std::string, ViewFn>& views() {
  static const std::map<std::string, ViewFn> all = {
      {"box", box_view},
      {"sphere", sphere_view},
      {"cylinder", cylinder_view},
      {"cone", cone_view},
      {"frustum", frustum_view},
      {"pentagonal_prism", pentagonal_prism_view},
      {"prism", prism_view},
      {"tetrahedron", tetrahedron_view}};
  return all;
}

}  // namespace

Eigen::Matrix3d object_rotation(const pipeline::ObjectResult& object) {
  Mat3 r = object.axes.transpose();  // rows are the axes: columns now
  if (r.determinant() < 0.0) r.col(2) = -r.col(2);
  return r;
}

double dimension(const pipeline::ObjectResult& object, const char* name) {
  for (const auto& [n, v] : object.dimensions) {
    if (n == name) return v;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::optional<OrientedBox> extent_box(const pipeline::ObjectResult& object) {
  const pipeline::Extent& e = object.extent;
  if (!e.center.allFinite() || !e.axes.allFinite() || !e.size.allFinite() || !(e.size.maxCoeff() > 0.0)) {
    return std::nullopt;
  }
  Mat3 r = e.axes.transpose();
  if (r.determinant() < 0.0) r.col(2) = -r.col(2);
  return OrientedBox{Frame{e.center, r}, e.size};
}

std::optional<SolidView> solid_view(const pipeline::ObjectResult& object, int circle_segments) {
  const auto it = views().find(object.shape);
  if (it == views().end()) return std::nullopt;
  if (!object.center.allFinite() || !object.axes.allFinite()) return std::nullopt;
  return it->second(object, Frame{object.center, object_rotation(object)}, circle_segments);
}

}  // namespace cloudshape::ros2
