// A cloud's recognition result as visualization_msgs/MarkerArray for RViz and Foxglove: the solid
// of every object (CUBE, SPHERE, CYLINDER, TRIANGLE_LIST) and a text label with its shape and size.
#pragma once

#include "config/ros2_config.hpp"
#include "io/pointcloud2.hpp"
#include "pipeline/result.hpp"
#include "visualization_msgs.h"

namespace cloudshape::ros2 {

// Every marker is stamped with `header` and has namespace result.source. markers[0] is a
// DELETEALL of that namespace (the previous cloud's markers go); then per object i: id 2i its
// solid (box: CUBE of its edges; sphere: SPHERE, scale = diameter; cylinder: CYLINDER along the
// marker's z, scale = diameter, diameter, height; cone, frustum, prisms, tetrahedron:
// TRIANGLE_LIST of its faces in its own frame), for an object without a solid the LINE_LIST of
// its extent's edges, none without an extent either; id 2i+1 a TEXT_VIEW_FACING label at its
// centre ("cylinder radius 3 height 8 (97%)", "unknown: <reason>").
visualization_msgs::msg::MarkerArray to_marker_array(const pipeline::RecognitionResult& result,
                                                     const io::RosHeader& header,
                                                     const config::Ros2Config& style);

// The label of an object as the text marker shows it.
std::string object_label(const pipeline::ObjectResult& object);

}  // namespace cloudshape::ros2
