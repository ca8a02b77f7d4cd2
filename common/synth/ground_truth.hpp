// Ground-truth description of a synthetic solid: kind, named dimensions and pose.
// Names, order and pose conventions follow shared/INTERFACE.md so results compare directly.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cloudshape::synth {

enum class ShapeKind { box, tetrahedron, pentagonal_prism, cone, cylinder, sphere };

// Every kind, in declaration order (handy for suites and parameterised tests).
const std::vector<ShapeKind>& all_shape_kinds();

std::string to_string(ShapeKind kind);
// nullopt for an unknown name rather than throwing: callers decide how to report it.
std::optional<ShapeKind> shape_kind_from_string(std::string_view name);

// Dimension names of a kind, in INTERFACE.md order (box: length, width, height; ...).
const std::vector<std::string>& dimension_names(ShapeKind kind);

// Row i of `axes` is the solid's i-th local axis expressed in world coordinates,
// so world = center + axes.transpose() * local.
struct Pose {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();

  Eigen::Vector3d to_world(const Eigen::Vector3d& local) const {
    return center + axes.transpose() * local;
  }
};

// Local frames (before posing), chosen so the pose matches INTERFACE.md:
//   box: centred, length along x, width along y, height along z.
//   tetrahedron (regular): centroid at origin, x from centroid to one vertex (the "apex",
//     normal to the opposite face), y towards one base vertex.
//   pentagonal_prism: centroid at origin, prism axis x, one pentagon vertex on +y.
//   cone: base circle centred at origin in the y-z plane, apex at (height, 0, 0).
//   cylinder: axis x from -height/2 to +height/2.
//   sphere: centred at origin.
struct SolidSpec {
  ShapeKind kind = ShapeKind::sphere;
  std::vector<std::pair<std::string, double>> dimensions;
  Pose pose;
};

// Looks a dimension up by name; throws std::invalid_argument if absent.
double dimension(const SolidSpec& spec, std::string_view name);

// Builds a validated spec from values in dimension_names(kind) order. Throws
// std::invalid_argument on a wrong count or a non-positive / non-finite value.
// Box values are sorted length >= width >= height and the pose axes permuted with them
// (the third axis is flipped if needed to keep the frame right-handed).
SolidSpec make_solid(ShapeKind kind, const std::vector<double>& values, const Pose& pose = {});

// Largest extent of the solid (box length, cone/cylinder max(height, diameter), ...).
double characteristic_size(const SolidSpec& spec);

// Total surface area of the closed solid.
double surface_area(const SolidSpec& spec);

}  // namespace cloudshape::synth
