#include "render/wireframe_shapes.hpp"

#include "geometry/polygon.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <string>

namespace cloudshape::render {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kCircleSegments = 72;

// The named dimension, or NaN when the result lacks it or it is not a positive length.
double dimension(const pipeline::ObjectResult& o, const std::string& name) {
  for (const auto& [key, value] : o.dimensions)
    if (key == name && std::isfinite(value) && value > 0.0) return value;
  return std::numeric_limits<double>::quiet_NaN();
}

bool all_lengths(std::initializer_list<double> values) {
  for (double v : values)
    if (std::isnan(v)) return false;
  return true;
}

Polyline segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return {{a, b}, false}; }

Polyline circle(const Eigen::Vector3d& center, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                double radius) {
  Polyline c{{}, true};
  for (int k = 0; k < kCircleSegments; ++k) {
    const double t = 2.0 * kPi * k / kCircleSegments;
    c.points.push_back(center + radius * (std::cos(t) * u + std::sin(t) * v));
  }
  return c;
}

}  // namespace

Wireframe extrusion(const Eigen::Vector3d& center, const Eigen::Matrix3d& axes,
                    const std::vector<Eigen::Vector2d>& polygon, double height) {
  const Eigen::Vector3d w = axes.row(0).transpose(), u = axes.row(1).transpose(),
                        v = axes.row(2).transpose();
  Polyline low{{}, true}, high{{}, true};
  Wireframe out;
  for (const Eigen::Vector2d& p : polygon) {
    const Eigen::Vector3d in_plane = center + p.x() * u + p.y() * v;
    low.points.push_back(in_plane - 0.5 * height * w);
    high.points.push_back(in_plane + 0.5 * height * w);
    out.lines.push_back(segment(low.points.back(), high.points.back()));
  }
  out.lines.push_back(std::move(low));
  out.lines.push_back(std::move(high));
  return out;
}

Wireframe round_solid(const Eigen::Vector3d& base, const Eigen::Matrix3d& axes, double radius,
                      double top_radius, double height, const Eigen::Vector3d& toward_viewer) {
  const Eigen::Vector3d w = axes.row(0).transpose(), u = axes.row(1).transpose(),
                        v = axes.row(2).transpose();
  const Eigen::Vector3d top = base + height * w;
  Wireframe out;
  out.lines.push_back(circle(base, u, v, radius));
  if (top_radius > 0.0) out.lines.push_back(circle(top, u, v, top_radius));
  // The side surface's normal at angle t is along height * radial(t) + (radius - top_radius) * w,
  // so its outline (normal across the line of sight) is where
  // height * rho * cos(t - phi) = -(radius - top_radius) * (toward_viewer . w).
  const double du = toward_viewer.dot(u), dv = toward_viewer.dot(v);
  const double rho = std::hypot(du, dv);
  const double c = rho > 1e-9 ? -(radius - top_radius) * toward_viewer.dot(w) / (height * rho) : 2.0;
  std::vector<double> angles;
  if (std::abs(c) < 1.0) {
    const double phi = std::atan2(dv, du), spread = std::acos(c);
    angles = {phi - spread, phi + spread};
  } else {  // seen along the axis: no outline, so four generators show the side
    angles = {0.0, 0.5 * kPi, kPi, 1.5 * kPi};
  }
  for (double t : angles) {
    const Eigen::Vector3d radial = std::cos(t) * u + std::sin(t) * v;
    out.lines.push_back(segment(base + radius * radial, top + top_radius * radial));
    out.lines.back().outline = angles.size() == 2;
  }
  return out;
}

Wireframe box_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d&) {
  const double l = dimension(o, "length"), w = dimension(o, "width"), h = dimension(o, "height");
  if (!all_lengths({l, w, h})) return {};
  // Length along axes[0] is the extrusion; width and height span the cross-section.
  const std::vector<Eigen::Vector2d> rect = {{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}};
  return extrusion(o.center, o.axes, rect, l);
}

Wireframe pentagonal_prism_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d&) {
  const double side = dimension(o, "side"), h = dimension(o, "height");
  if (!all_lengths({side, h})) return {};
  // axes[1] is the outward normal of one side face, so the corners sit 36 degrees either side.
  const double circumradius = side / (2.0 * std::sin(kPi / 5.0));
  return extrusion(o.center, o.axes, geometry::regular_polygon(5, circumradius, kPi / 5.0), h);
}

Wireframe tetrahedron_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d&) {
  const double edge = dimension(o, "edge");
  if (!all_lengths({edge})) return {};
  // The solver points axes[0] at the first corner and puts the second in the axes[0]-axes[1]
  // plane; seen from the centre, every two corners are acos(-1/3) apart.
  const double r = edge * std::sqrt(6.0) / 4.0;
  const double s = std::sqrt(8.0) / 3.0;
  const Eigen::Vector3d x = o.axes.row(0).transpose(), y = o.axes.row(1).transpose(),
                        z = o.axes.row(2).transpose();
  const Eigen::Vector3d v0 = o.center + r * x;
  const Eigen::Vector3d v1 = o.center + r * (-x / 3.0 + s * y);
  const Eigen::Vector3d v2 = o.center + r * (-x / 3.0 + s * (-0.5 * y + std::sqrt(0.75) * z));
  const Eigen::Vector3d v3 = o.center + r * (-x / 3.0 + s * (-0.5 * y - std::sqrt(0.75) * z));
  Wireframe out;
  out.lines.push_back({{v1, v2, v3}, true});
  for (const Eigen::Vector3d& v : {v1, v2, v3}) out.lines.push_back(segment(v0, v));
  return out;
}

Wireframe cylinder_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer) {
  const double r = dimension(o, "radius"), h = dimension(o, "height");
  if (!all_lengths({r, h})) return {};
  const Eigen::Vector3d base = o.center - 0.5 * h * o.axes.row(0).transpose();
  return round_solid(base, o.axes, r, r, h, toward_viewer);
}

Wireframe cone_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer) {
  const double r = dimension(o, "radius"), h = dimension(o, "height");
  if (!all_lengths({r, h})) return {};
  return round_solid(o.center, o.axes, r, 0.0, h, toward_viewer);
}

Wireframe sphere_wireframe(const pipeline::ObjectResult& o, const Eigen::Vector3d& toward_viewer) {
  const double r = dimension(o, "radius");
  if (!all_lengths({r})) return {};
  // The rim as seen, and two great circles across it so that the ball reads as a ball.
  const Eigen::Vector3d d = toward_viewer.normalized();
  Eigen::Vector3d u = d.unitOrthogonal();
  const Eigen::Vector3d v = d.cross(u);
  Wireframe out;
  out.lines.push_back(circle(o.center, u, v, r));
  out.lines.back().outline = true;
  const double tilt = kPi / 6.0;
  out.lines.push_back(circle(o.center, u, std::cos(tilt) * d + std::sin(tilt) * v, r));
  out.lines.push_back(circle(o.center, v, std::cos(tilt) * d - std::sin(tilt) * u, r));
  return out;
}

}  // namespace cloudshape::render
