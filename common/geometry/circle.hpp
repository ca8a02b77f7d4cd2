// Circles and spheres through or fitted to points: the circumcircle of a triangle
// (thesis eq. 3.7-3.8) and least-squares circle (in a plane) and sphere fits.
#pragma once

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

}  // namespace cloudshape::geometry
