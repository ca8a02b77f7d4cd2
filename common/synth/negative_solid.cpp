#include "synth/negative_solid.hpp"

#include <cmath>

#include "synth/pose.hpp"

namespace cloudshape::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A (u, v) grid wrapped into a closed surface by `at(u, v)`, u and v in [0, 1), both periodic
// (torus) or v running pole to pole (ellipsoid: rows at v = 0 and 1 collapse to the poles).
template <class F>
SolidMesh grid_surface(int nu, int nv, bool poles, F at) {
  SolidMesh m;
  const int rows = poles ? nv + 1 : nv;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < nu; ++i)
      m.vertices.push_back(at(static_cast<double>(i) / nu, static_cast<double>(j) / nv));
  const auto id = [&](int i, int j) { return static_cast<std::uint32_t>((j % rows) * nu + (i % nu)); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

SolidMesh polyhedron(PointList vertices, std::vector<Triangle> triangles) {
  SolidMesh m;
  m.vertices = std::move(vertices);
  m.triangles = std::move(triangles);
  return m;
}

SolidMesh local_mesh(NegativeKind kind, std::mt19937_64& rng, double size) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  switch (kind) {
    case NegativeKind::ellipsoid: {
      // Semi-axes a > b > c, each at least 25% above the next.
      const double a = 0.5 * size, b = a / (1.25 + 0.5 * u(rng)), c = b / (1.25 + 0.5 * u(rng));
      return grid_surface(96, 64, true, [&](double s, double t) {
        const double phi = 2.0 * kPi * s, theta = kPi * t;
        return Point(a * std::sin(theta) * std::cos(phi), b * std::sin(theta) * std::sin(phi),
                     c * std::cos(theta));
      });
    }
    case NegativeKind::torus: {
      const double major = 0.5 * size / (1.0 + (0.25 + 0.35 * u(rng)));
      const double minor = size * 0.5 - major;
      return grid_surface(128, 48, false, [&](double s, double t) {
        const double phi = 2.0 * kPi * s, theta = 2.0 * kPi * t;
        const double r = major + minor * std::cos(theta);
        return Point(r * std::cos(phi), r * std::sin(phi), minor * std::sin(theta));
      });
    }
    case NegativeKind::square_pyramid: {
      const double base = size * (0.6 + 0.4 * u(rng));
      const double h = size * (0.5 + 0.5 * u(rng)), b = 0.5 * base;
      return polyhedron({{-b, -b, 0}, {b, -b, 0}, {b, b, 0}, {-b, b, 0}, {0, 0, h}},
                        {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
    }
    case NegativeKind::octahedron: {
      const double a = 0.5 * size, b = a * (0.6 + 0.4 * u(rng)), c = a * (0.6 + 0.4 * u(rng));
      return polyhedron({{a, 0, 0}, {-a, 0, 0}, {0, b, 0}, {0, -b, 0}, {0, 0, c}, {0, 0, -c}},
                        {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
    }
    case NegativeKind::capsule: {
      // A cylinder's side between two hemispheres, rows evenly spaced along the profile's arc
      // length: a dome of a quarter turn, the straight side, the other dome.
      const double radius = size * (0.2 + 0.1 * u(rng)), straight = size - 2.0 * radius;
      const double dome = 0.5 * kPi * radius, profile = 2.0 * dome + straight;
      return grid_surface(96, 96, true, [&](double s, double t) {
        const double along = t * profile, phi = 2.0 * kPi * s;
        double r = radius, z = 0.0;
        if (along < dome) {
          r = radius * std::sin(along / radius);
          z = -0.5 * straight - radius * std::cos(along / radius);
        } else if (along < dome + straight) {
          z = along - dome - 0.5 * straight;
        } else {
          const double a = (along - dome - straight) / radius;
          r = radius * std::cos(a);
          z = 0.5 * straight + radius * std::sin(a);
        }
        return Point(r * std::cos(phi), r * std::sin(phi), z);
      });
    }
  }
  return {};
}

}  // namespace

const std::vector<NegativeKind>& all_negative_kinds() {
  static const std::vector<NegativeKind> kinds = {NegativeKind::ellipsoid, NegativeKind::torus,
                                                  NegativeKind::square_pyramid,
                                                  NegativeKind::octahedron, NegativeKind::capsule};
  return kinds;
}

std::string to_string(NegativeKind kind) {
  switch (kind) {
    case NegativeKind::ellipsoid: return "ellipsoid";
    case NegativeKind::torus: return "torus";
    case NegativeKind::square_pyramid: return "square_pyramid";
    case NegativeKind::octahedron: return "octahedron";
    case NegativeKind::capsule:
      return "capsule";
  }
  return "negative";
}

SolidMesh random_negative_solid(NegativeKind kind, std::mt19937_64& rng, double size) {
  SolidMesh m = local_mesh(kind, rng, size);
  const Pose pose = random_pose(rng, size);
  // The centroid of the surface is the solid's for every kind here but the pyramid, whose
  // centroid lies a quarter of its height above the base.
  Eigen::Vector3d local_center = Eigen::Vector3d::Zero();
  if (kind == NegativeKind::square_pyramid) local_center.z() = 0.25 * m.vertices[4].z();
  for (Point& p : m.vertices) p = pose.axes.transpose() * (p - local_center) + pose.center;
  m.center = pose.center;
  m.size = size;
  return m;
}

}  // namespace cloudshape::synth
