// An oriented plane n.x + d = 0 with unit normal, its least-squares fit, and the
// line where two planes meet.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/point_cloud.hpp"

namespace cloudshape::geometry {

struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit length
  double offset = 0.0;                                // n.x + offset = 0 on the plane

  double signed_distance(const Point& p) const { return normal.dot(p) + offset; }
  Point project(const Point& p) const { return p - signed_distance(p) * normal; }
};

struct Line {
  Point point = Point::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // unit length
};

// Plane through three points; nullopt when they are (nearly) collinear.
std::optional<Plane> plane_through(const Point& a, const Point& b, const Point& c);

// Total least squares plane of the indexed points (normal = smallest PCA eigenvector).
Plane fit_plane_least_squares(const PointList& points, const std::vector<std::uint32_t>& indices);

// Intersection of two planes; nullopt when they are parallel within `min_sin_angle`.
std::optional<Line> intersect_planes(const Plane& a, const Plane& b, double min_sin_angle = 1e-3);

// The point common to three planes; nullopt when they do not meet in a single point.
std::optional<Point> intersect_three_planes(const Plane& a, const Plane& b, const Plane& c);

// An orthonormal basis (u, v) of the plane orthogonal to `normal`.
void plane_basis(const Eigen::Vector3d& normal, Eigen::Vector3d& u, Eigen::Vector3d& v);

}  // namespace cloudshape::geometry
