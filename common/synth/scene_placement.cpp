// Random solids for tabletop scenes and exact flush placement from the support function.
// Proportions stay within about 1:4 so every solid is recognisable as its kind.
#include "synth/scene_placement.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "synth/resting_pose.hpp"
#include "synth/solid_support.hpp"

namespace cloudshape::synth {

namespace {

constexpr double kPi = 3.14159265358979323846;

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

std::vector<double> tabletop_dimensions(ShapeKind kind, std::mt19937_64& rng, double unit) {
  switch (kind) {
    case ShapeKind::box:
      return {uniform(rng, 0.06, 0.25) * unit, uniform(rng, 0.06, 0.25) * unit,
              uniform(rng, 0.06, 0.25) * unit};
    case ShapeKind::tetrahedron:
      return {uniform(rng, 0.08, 0.22) * unit};
    case ShapeKind::pentagonal_prism:
      return {uniform(rng, 0.04, 0.08) * unit, uniform(rng, 0.06, 0.2) * unit};
    case ShapeKind::cone:
      return {uniform(rng, 0.04, 0.09) * unit, uniform(rng, 0.08, 0.2) * unit};
    case ShapeKind::cylinder:
      return {uniform(rng, 0.03, 0.07) * unit, uniform(rng, 0.08, 0.22) * unit};
    case ShapeKind::sphere:
      return {uniform(rng, 0.03, 0.09) * unit};
  }
  return {};
}

}  // namespace

double lowest(const SolidSpec& spec, const Eigen::Vector3d& direction) {
  return -support(spec, -direction);
}

double highest(const SolidSpec& spec, const Eigen::Vector3d& direction) {
  return support(spec, direction);
}

void set_lowest(SolidSpec& spec, const Eigen::Vector3d& direction, double value) {
  translate(spec, (value - lowest(spec, direction)) * direction);
}

void set_highest(SolidSpec& spec, const Eigen::Vector3d& direction, double value) {
  translate(spec, (value - highest(spec, direction)) * direction);
}

SolidSpec resting_solid(ShapeKind kind, std::mt19937_64& rng, double unit) {
  SolidSpec spec = make_solid(kind, tabletop_dimensions(kind, rng, unit));
  place_at_rest(spec, rng);
  set_lowest(spec, Eigen::Vector3d::UnitZ(), 0.0);
  return spec;
}

SolidSpec aligned_box(std::mt19937_64& rng, double unit) {
  SolidSpec spec = make_solid(ShapeKind::box, tabletop_dimensions(ShapeKind::box, rng, unit));
  set_lowest(spec, Eigen::Vector3d::UnitZ(), 0.0);
  return spec;
}

SolidSpec standing_cylinder(std::mt19937_64& rng, double unit) {
  Pose pose;
  // The axis (local x) vertical; rows stay a right-handed frame.
  pose.axes << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  SolidSpec spec =
      make_solid(ShapeKind::cylinder, tabletop_dimensions(ShapeKind::cylinder, rng, unit), pose);
  set_lowest(spec, Eigen::Vector3d::UnitZ(), 0.0);
  return spec;
}

void yaw(SolidSpec& spec, double angle) {
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  spec.pose.axes = spec.pose.axes * turn.transpose();
}

void stack_on(SolidSpec& upper, const SolidSpec& lower, std::mt19937_64& rng) {
  yaw(upper, uniform(rng, 0.0, 2.0 * kPi));
  // The lower box's two horizontal axes span its top face; keep the upper centre in its inner
  // fifth on each side so the centre of mass is well inside the support.
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  const std::array<double, 3> half{dimension(lower, "length") / 2, dimension(lower, "width") / 2,
                                   dimension(lower, "height") / 2};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = lower.pose.axes.row(k).transpose();
    if (std::abs(axis.z()) < 0.5) offset += uniform(rng, -0.2, 0.2) * half[k] * axis;
  }
  const Eigen::Vector3d top = lower.pose.center + offset;
  translate(upper,
            Eigen::Vector3d(top.x() - upper.pose.center.x(), top.y() - upper.pose.center.y(), 0.0));
  set_lowest(upper, Eigen::Vector3d::UnitZ(), highest(lower, Eigen::Vector3d::UnitZ()));
}

}  // namespace cloudshape::synth
