// A synthetic scene with exact truth: flat structure (a table or floor, walls) and solids on it,
// each with its mOSD label (1 = the support plane, 2.. = walls, 20, 30, ... = the objects).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "synth/ground_truth.hpp"

namespace cloudshape::synth {

// A rectangle: centre, two orthonormal in-plane directions and the half extents along them.
struct SceneRectangle {
  std::string kind;  // "plane" (what objects stand on) or "wall"
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX(), v = Eigen::Vector3d::UnitY();
  double half_u = 1.0, half_v = 1.0;
  std::uint32_t label = 1;

  Eigen::Vector3d normal() const { return u.cross(v); }
};

struct SceneObject {
  SolidSpec solid;
  std::uint32_t label = 20;
};

struct Scene {
  std::vector<SceneRectangle> structure;
  std::vector<SceneObject> objects;
};

struct SceneHit {
  double t = 0.0;
  std::uint32_t label = 0;  // 0: nothing hit
};

// First surface along origin + t * direction (direction unit) for t in (0, t_max].
class SceneRayCaster {
 public:
  explicit SceneRayCaster(const Scene& scene);
  SceneHit cast(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                double t_max) const;

 private:
  const Scene& scene_;
  std::vector<double> radius_;
};

// The scene seen from another frame: every position p becomes rotation * (p - origin).
Scene transformed(const Scene& scene, const Eigen::Matrix3d& rotation,
                  const Eigen::Vector3d& origin);

}  // namespace cloudshape::synth
