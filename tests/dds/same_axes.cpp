// The axes part of the DDS "same result" check: which axes the contract fixes, and their sign.
// INTERFACE.md: sign free except cone/frustum axis 0; sphere any orthonormal set; box axes along edges.
#include "same_axes.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace cloudshape::testing {
namespace {

bool same_value(double a, double b, double tolerance) {
  return std::abs(a - b) <= tolerance * std::max({1.0, std::abs(a), std::abs(b)});
}

bool same_vector(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tolerance) {
  return (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

std::string row(const Eigen::Matrix3d& m, int i) {
  std::ostringstream s;
  s.precision(17);
  s << '[' << m(i, 0) << ", " << m(i, 1) << ", " << m(i, 2) << ']';
  return s.str();
}

// A free axis still has to be a unit vector orthogonal to the others.
std::string not_orthonormal(const Eigen::Matrix3d& axes, double tolerance) {
  const Eigen::Matrix3d gram = axes * axes.transpose();
  if ((gram - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= tolerance) return {};
  return "axes are not orthonormal: " + row(axes, 0) + " " + row(axes, 1) + " " + row(axes, 2);
}

// The axes the contract fixes for this object (the others only have to complete an
// orthonormal set), and whether axis 0 keeps its sign.
struct Fixed {
  std::vector<int> axes;
  bool signed_axis0 = false;
};

Fixed fixed_axes(const pipeline::ObjectResult& o, double tolerance) {
  if (o.shape == "sphere") return {{}, false};
  if (o.shape == "cone" || o.shape == "frustum") return {{0, 1, 2}, true};
  if (o.shape == "box" && o.dimensions.size() == 3) {
    // length >= width >= height: an equal pair leaves only its plane, known by the third axis.
    const bool lw = same_value(o.dimensions[0].second, o.dimensions[1].second, tolerance);
    const bool wh = same_value(o.dimensions[1].second, o.dimensions[2].second, tolerance);
    if (lw && wh) return {{}, false};
    if (lw) return {{2}, false};
    if (wh) return {{0}, false};
  }
  return {{0, 1, 2}, false};
}

}  // namespace

std::string axes_difference(const pipeline::ObjectResult& actual, const pipeline::ObjectResult& expected,
                            double tolerance) {
  if (std::string why = not_orthonormal(actual.axes, tolerance); !why.empty()) return why;
  const Fixed fixed = fixed_axes(expected, tolerance);
  for (int i : fixed.axes) {
    const Eigen::Vector3d a = actual.axes.row(i).transpose(), e = expected.axes.row(i).transpose();
    const bool sign_free = !(i == 0 && fixed.signed_axis0);
    if (same_vector(a, e, tolerance) || (sign_free && same_vector(a, -e, tolerance))) continue;
    return "axes[" + std::to_string(i) + "] is " + row(actual.axes, i) + ", expected " + row(expected.axes, i) +
           (sign_free ? " (either sign)" : " (this sign)");
  }
  return {};
}

}  // namespace cloudshape::testing
