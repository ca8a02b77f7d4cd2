#include "synth/resting_pose.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "synth/pose.hpp"
#include "synth/solid_geometry.hpp"

namespace cloudshape::synth {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Outward unit normal (local frame) of the face the solid rests on.
Eigen::Vector3d resting_face_normal(const SolidSpec& spec, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const bool end_face = u(rng) < 0.5;  // a cap or base rather than a side
  const double phi = 2.0 * kPi * u(rng);
  const Eigen::Vector3d radial(0.0, std::cos(phi), std::sin(phi));
  const double sign = u(rng) < 0.5 ? -1.0 : 1.0;
  const auto away_from_origin = [](const Eigen::Vector3d& n, const Eigen::Vector3d& on_face) {
    return n.dot(on_face) < 0.0 ? Eigen::Vector3d(-n) : n;
  };
  switch (spec.kind) {
    case ShapeKind::box:
      return sign * Eigen::Vector3d::Unit(std::uniform_int_distribution<int>(0, 2)(rng));
    case ShapeKind::tetrahedron: {
      const auto v = tetrahedron_vertices(dimension(spec, "edge"));
      const int skip = std::uniform_int_distribution<int>(0, 3)(rng);
      const auto& a = v[(skip + 1) % 4];
      const Eigen::Vector3d n = (v[(skip + 2) % 4] - a).cross(v[(skip + 3) % 4] - a).normalized();
      return away_from_origin(n, a);
    }
    case ShapeKind::pentagonal_prism: {
      if (end_face) return sign * Eigen::Vector3d::UnitX();
      const auto v = pentagon_vertices(dimension(spec, "side"));
      const int k = std::uniform_int_distribution<int>(0, 4)(rng);
      const Eigen::Vector3d n = (v[(k + 1) % 5] - v[k]).cross(Eigen::Vector3d::UnitX()).normalized();
      return away_from_origin(n, v[k]);
    }
    case ShapeKind::cone: {
      if (end_face) return -Eigen::Vector3d::UnitX();  // the base; the apex points up
      const double r = dimension(spec, "radius"), h = dimension(spec, "height");
      const double slant = std::hypot(r, h);
      return (r / slant) * Eigen::Vector3d::UnitX() + (h / slant) * radial;
    }
    case ShapeKind::cylinder:
      return end_face ? Eigen::Vector3d(sign * Eigen::Vector3d::UnitX()) : radial;
    case ShapeKind::sphere:
      break;
  }
  return random_rotation(rng).col(0);
}

}  // namespace

void place_at_rest(SolidSpec& spec, std::mt19937_64& rng) {
  const Eigen::Vector3d down = resting_face_normal(spec, rng);
  const Eigen::Matrix3d lay = Eigen::Quaterniond::FromTwoVectors(down, -Eigen::Vector3d::UnitZ())
                                  .toRotationMatrix();
  const double yaw = std::uniform_real_distribution<double>(0.0, 2.0 * kPi)(rng);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // local -> world is turn * lay; pose.axes holds the local axes as rows (world -> local).
  spec.pose.axes = (turn * lay).transpose();
}

}  // namespace cloudshape::synth
