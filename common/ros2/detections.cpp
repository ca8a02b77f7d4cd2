// A cloud's recognition result as vision_msgs/Detection3DArray: one Detection3D per object.
#include "ros2/detections.hpp"

#include <string>

#include "ros2/messages.hpp"
#include "ros2/solid_view.hpp"

namespace cloudshape::ros2 {
namespace {

// A solid's box needs no circle detail: the box of the mesh is exact at any segment count that
// is a multiple of 4 (the circle's extreme points are vertices).
constexpr int kBoxSegments = 4;

vision_msgs::msg::Detection3D to_detection(const pipeline::ObjectResult& object, std::size_t index,
                                           const std_msgs::msg::Header& header) {
  const Frame pose{object.center, object_rotation(object)};
  vision_msgs::msg::Detection3D out;
  out.header(header);
  out.id(std::to_string(index));
  vision_msgs::msg::ObjectHypothesisWithPose hypothesis;
  hypothesis.hypothesis().class_id(object.shape);
  hypothesis.hypothesis().score(object.confidence);
  hypothesis.pose().pose(to_pose(pose));
  out.results().push_back(std::move(hypothesis));
  const std::optional<SolidView> view = solid_view(object, kBoxSegments);
  const std::optional<OrientedBox> extent = extent_box(object);
  const OrientedBox box = view ? view->box : extent ? *extent : OrientedBox{pose, Eigen::Vector3d::Zero()};
  out.bbox().center(to_pose(box.frame));
  out.bbox().size(to_vector3(box.size));
  return out;
}

}  // namespace

vision_msgs::msg::Detection3DArray to_detection_array(const pipeline::RecognitionResult& result,
                                                      const io::RosHeader& header) {
  vision_msgs::msg::Detection3DArray out;
  out.header(to_msg(header));
  for (std::size_t i = 0; i < result.objects.size(); ++i) {
    out.detections().push_back(to_detection(result.objects[i], i, out.header()));
  }
  return out;
}

}  // namespace cloudshape::ros2
