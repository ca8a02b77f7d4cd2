// Circles and spheres through or fitted to points: the circumcircle of a triangle
// (thesis eq. 3.7-3.8) and least-squares circle (in a plane) and sphere fits.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::geometry {

struct Circle3 {
  Point center = Point::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double radius = 0.0;
};

struct SphereFit {
  Point center = Point::Zero();
  double radius = 0.0;
  double rms = 0.0;  // root mean square of |p - center| - radius
};

// Circle through three points; nullopt when they are (nearly) collinear.
std::optional<Circle3> circumcircle(const Point& a, const Point& b, const Point& c);

// Geometric least-squares circle of the indexed points projected on the plane through
// `origin` with normal `normal` (algebraic start, then Gauss-Newton). nullopt if < 3 points.
std::optional<Circle3> fit_circle_in_plane(const PointList& points,
                                           const std::vector<std::uint32_t>& indices,
                                           const Point& origin, const Eigen::Vector3d& normal);

// Geometric least-squares sphere (algebraic start, then Gauss-Newton). nullopt if < 4 points
// or degenerate (coplanar).
std::optional<SphereFit> fit_sphere(const PointList& points,
                                    const std::vector<std::uint32_t>& indices);
std::optional<SphereFit> fit_sphere(const PointList& points);

// The widest gap, in radians, between `angles` (radians, atan2's range) around the circle, the
// wrap from the last to the first included; sorts `angles`. At least one angle: one alone leaves
// the whole turn.
inline double widest_angular_gap(std::vector<double>& angles) {
  constexpr double kTurn = 2.0 * 3.14159265358979323846;
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + kTurn - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k) gap = std::max(gap, angles[k] - angles[k - 1]);
  return gap;
}

}  // namespace cloudshape::geometry
