// The tetrahedron is regular and the prism's pentagon is regular, with the stated sizes.
#include "synth/ground_truth.hpp"
#include "synth/solid_geometry.hpp"

#include <gtest/gtest.h>

namespace cloudshape::synth {
namespace {

TEST(RegularPolyhedra, TetrahedronHasSixEqualEdgesAndCentroidAtOrigin) {
  for (double edge : {0.1, 1.0, 37.5}) {
    const auto v = tetrahedron_vertices(edge);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
      sum += v[i];
      for (int j = i + 1; j < 4; ++j) EXPECT_NEAR((v[i] - v[j]).norm(), edge, 1e-12 * edge);
    }
    EXPECT_LT(sum.norm(), 1e-12 * edge);
    // Apex on +x, opposite face normal to x.
    EXPECT_NEAR(v[0].y(), 0.0, 1e-15);
    EXPECT_NEAR(v[0].z(), 0.0, 1e-15);
    EXPECT_NEAR(v[1].x(), v[2].x(), 1e-12 * edge);
    EXPECT_NEAR(v[1].x(), v[3].x(), 1e-12 * edge);
  }
}

TEST(RegularPolyhedra, PentagonHasFiveEqualSidesAndEqualAngles) {
  for (double side : {0.2, 3.0, 50.0}) {
    const auto v = pentagon_vertices(side);
    for (int k = 0; k < 5; ++k) {
      EXPECT_NEAR((v[(k + 1) % 5] - v[k]).norm(), side, 1e-12 * side);
      EXPECT_NEAR((v[(k + 2) % 5] - v[k]).norm(), side * (1 + std::sqrt(5.0)) / 2, 1e-12 * side);
      EXPECT_EQ(v[k].x(), 0.0);
    }
  }
}

TEST(RegularPolyhedra, SurfaceAreasMatchClosedForms) {
  EXPECT_NEAR(surface_area(make_solid(ShapeKind::tetrahedron, {2.0})), 4 * std::sqrt(3.0), 1e-12);
  // Regular pentagon area = (1/4) sqrt(5(5+2 sqrt 5)) s^2.
  const double pent = 0.25 * std::sqrt(5 * (5 + 2 * std::sqrt(5.0)));
  EXPECT_NEAR(surface_area(make_solid(ShapeKind::pentagonal_prism, {1.0, 2.0})), 2 * pent + 10.0,
              1e-12);
  EXPECT_NEAR(surface_area(make_solid(ShapeKind::box, {1.0, 2.0, 3.0})), 22.0, 1e-12);
}

TEST(ShapeKindNames, RoundTripAndRejectUnknown) {
  for (ShapeKind kind : all_shape_kinds()) EXPECT_EQ(shape_kind_from_string(to_string(kind)), kind);
  EXPECT_EQ(to_string(ShapeKind::pentagonal_prism), "pentagonal_prism");
  EXPECT_FALSE(shape_kind_from_string("unknown").has_value());
  EXPECT_FALSE(shape_kind_from_string("Box").has_value());
}

}  // namespace
}  // namespace cloudshape::synth
