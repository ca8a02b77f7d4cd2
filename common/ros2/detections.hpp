// A cloud's recognition result as vision_msgs/Detection3DArray: one Detection3D per object, its
// shape as class_id, confidence as score, the solid's pose, and the solid's own box as bbox.
#pragma once

#include "io/pointcloud2.hpp"
#include "pipeline/result.hpp"
#include "vision_msgs.h"

namespace cloudshape::ros2 {

// Every header is `header` (the input cloud's). Per object i: id "i"; results[0]: class_id =
// shape name (INTERFACE.md), score = confidence, pose = pose.center with the orientation whose
// x, y, z are pose.axes[0..2] (axes[2] reversed if they are left-handed), zero covariance;
// bbox: the solid's box along those axes (box: length, width, height; cylinder: height, then
// the diameter twice, centred on the axis midpoint; cone and frustum: the same from the base
// circle to the apex or smaller end; sphere: the diameter; prisms, tetrahedron: around their
// vertices); an object without a solid (unknown) has its extent as bbox, one without an extent
// either (an error) a bbox of size 0 at its pose.
vision_msgs::msg::Detection3DArray to_detection_array(const pipeline::RecognitionResult& result,
                                                      const io::RosHeader& header);

}  // namespace cloudshape::ros2
