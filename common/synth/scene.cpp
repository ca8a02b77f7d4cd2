// Ray casting through a scene (exact rectangle and solid intersections, nearest wins) and the
// change of frame that puts a scene into its sensor's coordinates.
#include "synth/scene.hpp"

#include <cmath>

#include "synth/solid_ray.hpp"
#include "synth/solid_support.hpp"

namespace cloudshape::synth {

namespace {

std::optional<double> rectangle_hit(const SceneRectangle& rect, const Eigen::Vector3d& origin,
                                    const Eigen::Vector3d& direction) {
  const Eigen::Vector3d n = rect.normal();
  const double facing = n.dot(direction);
  if (facing == 0.0) return std::nullopt;
  const double t = n.dot(rect.center - origin) / facing;
  const Eigen::Vector3d local = origin + t * direction - rect.center;
  if (std::abs(local.dot(rect.u)) > rect.half_u || std::abs(local.dot(rect.v)) > rect.half_v)
    return std::nullopt;
  return t;
}

}  // namespace

SceneRayCaster::SceneRayCaster(const Scene& scene) : scene_(scene) {
  for (const auto& object : scene.objects) radius_.push_back(bounding_radius(object.solid));
}

SceneHit SceneRayCaster::cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                              double t_max) const {
  SceneHit best;
  double nearest = t_max;
  for (const auto& rect : scene_.structure) {
    const auto t = rectangle_hit(rect, origin, direction);
    if (t && *t > 0.0 && *t <= nearest) nearest = *t, best = {*t, rect.label};
  }
  for (std::size_t k = 0; k < scene_.objects.size(); ++k) {
    const auto t = first_hit(scene_.objects[k].solid, radius_[k], origin, direction, 0.0, nearest);
    // A solid standing on the plane meets it in a face: the solid's point wins the tie.
    if (t && *t <= nearest) nearest = *t, best = {*t, scene_.objects[k].label};
  }
  return best;
}

Scene transformed(const Scene& scene, const Eigen::Matrix3d& rotation,
                  const Eigen::Vector3d& origin) {
  Scene out = scene;
  for (auto& rect : out.structure) {
    rect.center = rotation * (rect.center - origin);
    rect.u = rotation * rect.u;
    rect.v = rotation * rect.v;
  }
  for (auto& object : out.objects) {
    object.solid.pose.center = rotation * (object.solid.pose.center - origin);
    // Rows are the local axes in the old frame; each turns with the frame.
    object.solid.pose.axes = object.solid.pose.axes * rotation.transpose();
  }
  return out;
}

}  // namespace cloudshape::synth
