// Convex hull of a face's points in its plane, then the residual of a circle fitted to the
// hull's outline and the hull's fill of its minimum-area enclosing rectangle (rotating calipers).
#include "pipeline/face_outline.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/convex_hull.hpp"
#include "geometry/plane.hpp"

namespace cloudshape::pipeline {
namespace {

using Vec2 = Eigen::Vector2d;

double polygon_area(const std::vector<Vec2>& h) {
  double a = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Vec2& p = h[i];
    const Vec2& q = h[(i + 1) % h.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * std::abs(a);
}

// The smallest enclosing rectangle has a side along one hull edge.
double min_rectangle_area(const std::vector<Vec2>& h) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Vec2 e = h[(i + 1) % h.size()] - h[i];
    if (!(e.norm() > 0.0)) continue;
    const Vec2 u = e.normalized(), v(-u.y(), u.x());
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    for (const Vec2& p : h) {
      u0 = std::min(u0, p.dot(u));
      u1 = std::max(u1, p.dot(u));
      v0 = std::min(v0, p.dot(v));
      v1 = std::max(v1, p.dot(v));
    }
    best = std::min(best, (u1 - u0) * (v1 - v0));
  }
  return best;
}

// Points evenly spaced along the hull's perimeter, so that long straight edges weigh as much
// as they are long (hull vertices crowd where the outline curves).
std::vector<Vec2> perimeter_samples(const std::vector<Vec2>& h, std::size_t count) {
  double perimeter = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) perimeter += (h[(i + 1) % h.size()] - h[i]).norm();
  std::vector<Vec2> out;
  if (!(perimeter > 0.0)) return out;
  const double step = perimeter / static_cast<double>(count);
  double carried = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Vec2 a = h[i], b = h[(i + 1) % h.size()];
    const double len = (b - a).norm();
    double t = carried;
    for (; t < len; t += step) out.push_back(a + (b - a) * (t / len));
    carried = t - len;
  }
  return out;
}

}  // namespace

FaceOutline face_outline(const PointList& cloud, const DetectedPlane& face, double max_circle_rms,
                         double max_circle_harmonic, double min_rect_fill) {
  FaceOutline out;
  if (face.inliers.size() < 10) return out;
  Eigen::Vector3d u, v;
  geometry::plane_basis(face.plane.normal, u, v);
  Point origin = Point::Zero();
  for (std::uint32_t i : face.inliers) origin += cloud[i];
  origin /= static_cast<double>(face.inliers.size());
  std::vector<Vec2> flat;
  flat.reserve(face.inliers.size());
  for (std::uint32_t i : face.inliers) {
    const Eigen::Vector3d d = cloud[i] - origin;
    flat.emplace_back(d.dot(u), d.dot(v));
  }
  const std::vector<Vec2> hull = geometry::convex_hull_2d(std::move(flat));
  if (hull.size() < 3) return out;
  const double area = polygon_area(hull);
  const double rect = min_rectangle_area(hull);
  if (!(area > 0.0) || !(rect > 0.0)) return out;
  out.rect_fill = area / rect;

  // Algebraic (Kasa) circle: x^2 + y^2 + D x + E y + F = 0, least squares; exact enough for
  // an outline that is a circle, and its residual is the test.
  const std::vector<Vec2> s = perimeter_samples(hull, 128);
  if (s.size() < 8) return out;
  Eigen::MatrixXd a(s.size(), 3);
  Eigen::VectorXd b(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    a(i, 0) = s[i].x();
    a(i, 1) = s[i].y();
    a(i, 2) = 1.0;
    b(i) = -s[i].squaredNorm();
  }
  const Eigen::Vector3d x = a.colPivHouseholderQr().solve(b);
  const Vec2 c(-0.5 * x(0), -0.5 * x(1));
  const double r2 = c.squaredNorm() - x(2);
  if (!(r2 > 0.0)) return out;
  out.radius = std::sqrt(r2);
  double sum = 0.0;
  for (const Vec2& p : s) sum += std::pow((p - c).norm() - out.radius, 2);
  out.circle_rms = std::sqrt(sum / static_cast<double>(s.size())) / out.radius;
  for (int k = 3; k <= 8; ++k) {
    double re = 0.0, im = 0.0;
    for (const Vec2& p : s) {
      const double angle = std::atan2(p.y() - c.y(), p.x() - c.x());
      const double e = (p - c).norm() - out.radius;
      re += e * std::cos(k * angle);
      im += e * std::sin(k * angle);
    }
    const double amplitude = 2.0 * std::hypot(re, im) / static_cast<double>(s.size()) / out.radius;
    out.polygon_harmonic = std::max(out.polygon_harmonic, amplitude);
  }
  out.center = origin + c.x() * u + c.y() * v;
  if (out.circle_rms <= max_circle_rms && out.polygon_harmonic <= max_circle_harmonic && out.rect_fill < min_rect_fill)
    out.kind = OutlineKind::circle;
  else if (out.rect_fill >= min_rect_fill) out.kind = OutlineKind::rectangle;
  return out;
}

}  // namespace cloudshape::pipeline
