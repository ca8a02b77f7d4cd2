// Area-uniformity: each patch receives its share of the area, within 3 binomial sigmas.
#include "surface_oracle.hpp"
#include "synth/pose.hpp"
#include "synth/sample_solid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace cloudshape::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kN = 200000;

// Expects count/n == p within 3 binomial standard deviations.
void expect_fraction(std::size_t count, std::size_t n, double p, const std::string& what) {
  const double sigma = std::sqrt(p * (1.0 - p) / static_cast<double>(n));
  EXPECT_NEAR(static_cast<double>(count) / n, p, 3.0 * sigma) << what;
}

std::size_t count_local(const SolidSpec& spec, const PointList& points,
                        const std::function<bool(const Eigen::Vector3d&)>& predicate) {
  std::size_t count = 0;
  for (const auto& p : points) count += predicate(testing::to_local(spec.pose, p)) ? 1 : 0;
  return count;
}

SolidSpec posed(ShapeKind kind, std::vector<double> dims, std::mt19937_64& rng) {
  return make_solid(kind, dims, random_pose(rng, 10.0));
}

TEST(AreaUniformity, BoxFacesGetTheirAreaShare) {
  std::mt19937_64 rng(7);
  const SolidSpec spec = posed(ShapeKind::box, {6.0, 3.0, 1.0}, rng);
  const auto points = sample_solid_surface(spec, kN, rng);
  const Eigen::Vector3d half(3.0, 1.5, 0.5);
  const double area = surface_area(spec);
  for (int k = 0; k < 3; ++k)
    for (double sign : {1.0, -1.0}) {
      const auto count = count_local(spec, points, [&](const Eigen::Vector3d& q) {
        return std::abs(q[k] - sign * half[k]) < 1e-9;
      });
      const double face = 4.0 * half[(k + 1) % 3] * half[(k + 2) % 3];
      expect_fraction(count, kN, face / area, "box face " + std::to_string(k));
    }
}

TEST(AreaUniformity, BoxFaceInteriorIsUniform) {
  std::mt19937_64 rng(8);
  const SolidSpec spec = make_solid(ShapeKind::box, {2.0, 2.0, 2.0});
  const auto points = sample_solid_surface(spec, kN, rng);
  // On the +x face, the inner square of half the side holds a quarter of the face's points.
  const auto face = count_local(spec, points, [](const auto& q) { return q.x() > 1.0 - 1e-12; });
  const auto inner = count_local(spec, points, [](const auto& q) {
    return q.x() > 1.0 - 1e-12 && std::abs(q.y()) < 0.5 && std::abs(q.z()) < 0.5;
  });
  expect_fraction(inner, face, 0.25, "inner square");
}

TEST(AreaUniformity, ConeBaseVersusLateralAndAlongTheSlant) {
  std::mt19937_64 rng(9);
  const double r = 2.0, h = 5.0;
  const SolidSpec spec = posed(ShapeKind::cone, {r, h}, rng);
  const auto points = sample_solid_surface(spec, kN, rng);
  const double base = kPi * r * r, lateral = kPi * r * std::hypot(r, h);
  const auto on_base =
      count_local(spec, points, [](const auto& q) { return std::abs(q.x()) < 1e-9; });
  expect_fraction(on_base, kN, base / (base + lateral), "cone base");
  // The lateral band nearer the base than half height is a frustum of 3/4 of the lateral area.
  const auto lower = count_local(
      spec, points, [&](const auto& q) { return std::abs(q.x()) >= 1e-9 && q.x() < h / 2; });
  expect_fraction(lower, kN - on_base, 0.75, "cone lower half of lateral surface");
  // Base disk: radius r/2 holds a quarter of the base.
  const auto inner = count_local(spec, points, [&](const auto& q) {
    return std::abs(q.x()) < 1e-9 && std::hypot(q.y(), q.z()) < r / 2;
  });
  expect_fraction(inner, on_base, 0.25, "cone base inner disk");
}

TEST(AreaUniformity, CylinderCapsVersusLateral) {
  std::mt19937_64 rng(10);
  const double r = 1.5, h = 4.0;
  const SolidSpec spec = posed(ShapeKind::cylinder, {r, h}, rng);
  const auto points = sample_solid_surface(spec, kN, rng);
  const double cap = kPi * r * r, side = 2 * kPi * r * h;
  const auto top = count_local(spec, points, [&](const auto& q) { return q.x() > h / 2 - 1e-9; });
  const auto bottom =
      count_local(spec, points, [&](const auto& q) { return q.x() < -h / 2 + 1e-9; });
  expect_fraction(top, kN, cap / (2 * cap + side), "cylinder top cap");
  expect_fraction(bottom, kN, cap / (2 * cap + side), "cylinder bottom cap");
  const auto low_side = count_local(spec, points, [&](const auto& q) {
    return std::abs(q.x()) < h / 2 - 1e-9 && q.x() < -h / 4;
  });
  expect_fraction(low_side, kN - top - bottom, 0.25, "cylinder lateral quarter");
}

TEST(AreaUniformity, SphereCapsAndOctants) {
  std::mt19937_64 rng(11);
  const SolidSpec spec = posed(ShapeKind::sphere, {3.0}, rng);
  const auto points = sample_solid_surface(spec, kN, rng);
  // Archimedes: a cap of height r/2 on any axis holds a quarter of the area.
  for (int k = 0; k < 3; ++k) {
    const auto cap = count_local(spec, points, [&](const auto& q) { return q[k] > 1.5; });
    expect_fraction(cap, kN, 0.25, "sphere cap axis " + std::to_string(k));
  }
  const auto octant =
      count_local(spec, points, [](const auto& q) { return (q.array() > 0).all(); });
  expect_fraction(octant, kN, 0.125, "sphere octant");
}

TEST(AreaUniformity, PentagonalPrismCapsSidesAndSectors) {
  std::mt19937_64 rng(12);
  const double s = 2.0, h = 3.0;
  const SolidSpec spec = posed(ShapeKind::pentagonal_prism, {s, h}, rng);
  const auto points = sample_solid_surface(spec, kN, rng);
  const double r = pentagon_circumradius(s);
  const double cap = 2.5 * r * r * std::sin(2 * kPi / 5);
  const double total = 2 * cap + 5 * s * h;
  const auto top = count_local(spec, points, [&](const auto& q) { return q.x() > h / 2 - 1e-9; });
  expect_fraction(top, kN, cap / total, "prism top cap");
  // The top cap's points inside the half-scale pentagon: a quarter of the cap.
  const auto half_scale =
      testing::polyhedron_faces(make_solid(ShapeKind::pentagonal_prism, {s / 2, h}));
  const auto inner = count_local(spec, points, [&](const auto& q) {
    if (q.x() < h / 2 - 1e-9) return false;
    for (std::size_t f = 2; f < half_scale.size(); ++f)
      if (half_scale[f].normal.dot(q) > half_scale[f].offset) return false;
    return true;
  });
  expect_fraction(inner, top, 0.25, "prism cap inner pentagon");
  const auto faces = testing::polyhedron_faces(spec);
  for (std::size_t f = 2; f < faces.size(); ++f) {
    const auto side = count_local(spec, points, [&](const auto& q) {
      return std::abs(faces[f].normal.dot(q) - faces[f].offset) < 1e-9 &&
             std::abs(q.x()) < h / 2 - 1e-9;
    });
    expect_fraction(side, kN, s * h / total, "prism side " + std::to_string(f));
  }
}

TEST(AreaUniformity, TetrahedronFacesAreEqual) {
  std::mt19937_64 rng(13);
  const SolidSpec spec = posed(ShapeKind::tetrahedron, {4.0}, rng);
  const auto points = sample_solid_surface(spec, kN, rng);
  for (const auto& f : testing::polyhedron_faces(spec)) {
    const auto count = count_local(
        spec, points, [&](const auto& q) { return std::abs(f.normal.dot(q) - f.offset) < 1e-9; });
    expect_fraction(count, kN, 0.25, "tetrahedron face");
  }
}

}  // namespace
}  // namespace cloudshape::synth
