// What a recognised solid looks like to ROS 2: its own bounding box, from its dimensions, and the
// RViz marker that draws it. One function per shape (solid_view.cpp): a new shape is one more entry.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "pipeline/result.hpp"

namespace cloudshape::ros2 {

// A rigid frame in the cloud's frame: rotation's columns are its x, y, z axes (right-handed).
struct Frame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

// A box of `size` along the rotation's columns around `center` (vision_msgs BoundingBox3D).
struct OrientedBox {
  Frame frame;  // origin: the box's centre
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
};

// The RViz primitive a solid is drawn with.
enum class Primitive { cube, sphere, cylinder, triangles };

struct SolidView {
  OrientedBox box;  // the solid's own box: box edges, cylinder and cone: height then diameters, ...
  Primitive primitive = Primitive::triangles;
  Frame marker_frame;   // the marker's pose; a cylinder's axis is its z, as RViz draws one
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();  // cube: edges; sphere, cylinder: diameters (and height)
  std::vector<Eigen::Vector3d> triangles;  // Primitive::triangles: three vertices a face, in marker_frame
};

// The object's axes as the columns of a right-handed rotation (axes[2] reversed when the three are
// left-handed: the contract leaves its sign free for every shape).
Eigen::Matrix3d object_rotation(const pipeline::ObjectResult& object);

// The value of dimension `name`, NaN when the object has none of that name.
double dimension(const pipeline::ObjectResult& object, const char* name);

// The view of a solid, nullopt for an unknown object, a shape without a view or dimensions that
// are missing or not positive. `circle_segments` (>= 3) approximates the circles of cones and
// frusta; a prism is its polygon extruded, a tetrahedron its own vertices when it has them.
std::optional<SolidView> solid_view(const pipeline::ObjectResult& object, int circle_segments);

// The object's extent (the oriented box of its own points), nullopt when it has none (size 0).
std::optional<OrientedBox> extent_box(const pipeline::ObjectResult& object);

}  // namespace cloudshape::ros2
