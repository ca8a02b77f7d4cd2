// Every object carries an extent that holds all its points and is tight on what they are:
// a posed box's extent is the box, an unknown object's still bounds it.
#include <gtest/gtest.h>

#include <random>

#include "new_shapes_support.hpp"
#include "synth/negative_solid.hpp"
#include "synth/pose.hpp"

namespace cloudshape::newshapes {
namespace {

void expect_bounds(const pipeline::ObjectResult& o, const PointList& cloud, double slack) {
  std::size_t outside = 0;
  for (const Point& p : cloud) {
    const Eigen::Vector3d l = o.extent.axes * (p - o.extent.center);
    for (int k = 0; k < 3; ++k) outside += std::abs(l[k]) > 0.5 * o.extent.size[k] + slack;
  }
  // Preprocessing drops a few isolated points; what it keeps must all lie inside.
  EXPECT_LE(outside, cloud.size() / 1000) << "points outside the extent";
  EXPECT_LT((o.extent.axes * o.extent.axes.transpose() - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GE(o.extent.size[0], o.extent.size[1]);
  EXPECT_GE(o.extent.size[1], o.extent.size[2]);
}

// A 60 x 30 x 12 box in a random pose (as a mesh): extent = the box within 1% of its length.
TEST(Extent, BoxExtentIsTheBox) {
  std::mt19937_64 rng(5);
  const synth::Pose pose = synth::random_pose(rng, 50.0);
  const Eigen::Vector3d h(30, 15, 6);
  std::array<Eigen::Vector3d, 8> c;
  for (int i = 0; i < 8; ++i)
    c[i] = pose.to_world(Eigen::Vector3d(i & 1 ? h.x() : -h.x(), i & 2 ? h.y() : -h.y(), i & 4 ? h.z() : -h.z()));
  synth::SolidMesh box;
  box.vertices.assign(c.begin(), c.end());
  box.triangles = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                   {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  box.size = 60.0;
  const PointList cloud = sample(box, 20000, 0.0, 6);
  const pipeline::ObjectResult o = recognise_one(cloud);
  EXPECT_EQ(o.shape, "box");
  expect_bounds(o, cloud, 1e-9);
  EXPECT_NEAR(o.extent.size[0], 60.0, 0.6);
  EXPECT_NEAR(o.extent.size[1], 30.0, 0.6);
  EXPECT_NEAR(o.extent.size[2], 12.0, 0.6);
  EXPECT_LT((o.extent.center - pose.center).norm(), 0.6);
  EXPECT_NEAR(std::abs(o.extent.axes.row(0).dot(pose.axes.row(0))), 1.0, 1e-3);
}

// A torus is no shape: unknown, but its extent is still the torus' box (2R+2r, 2R+2r, 2r).
TEST(Extent, UnknownObjectHasItsExtent) {
  std::mt19937_64 rng(7);
  const synth::SolidMesh torus = synth::random_negative_solid(synth::NegativeKind::torus, rng, 80.0);
  const PointList cloud = sample(torus, 20000, 0.0, 8);
  const pipeline::ObjectResult o = recognise_one(cloud);
  EXPECT_EQ(o.shape, "unknown") << o.reason;
  expect_bounds(o, cloud, 1e-9);
  EXPECT_NEAR(o.extent.size[0], 80.0, 1.6);
  EXPECT_NEAR(o.extent.size[1], 80.0, 1.6);
  EXPECT_LT(o.extent.size[2], 0.7 * 80.0);
  EXPECT_LT((o.extent.center - torus.center).norm(), 1.0);
}

}  // namespace
}  // namespace cloudshape::newshapes
