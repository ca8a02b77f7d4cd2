// The bench's view classification: which faces of a new shape a view's points lie on, and whether
// they determine the solid (a prism: a cap and a side; a tetrahedron: two faces; a frustum: its side).
#include <gtest/gtest.h>

#include <random>

#include "synth/mesh_sampling.hpp"
#include "synth/mesh_solids.hpp"
#include "synth/mesh_visibility.hpp"
#include "view_faces.hpp"

namespace cloudshape::bench {
namespace {

// Points the camera at `camera` sees of the mesh (noise-free, as the bench classifies them).
PointList seen(const synth::SolidMesh& mesh, const Eigen::Vector3d& camera) {
  std::mt19937_64 rng(7);
  const synth::MeshVisibility visibility(mesh.vertices, mesh.triangles);
  return visibility.visible(synth::sample_mesh_surface(mesh.vertices, mesh.triangles, 20000, rng), camera);
}

const geometry::Polygon2 kTriangle = {{-20, -10}, {20, -10}, {0, 25}};

TEST(ViewFaces, PrismNeedsItsCapAndASide) {
  const synth::Pose pose;  // axis along x, the triangle in y z
  const synth::SolidMesh mesh = synth::prism_mesh(kTriangle, 60.0, pose);
  // Straight at a cap: the cap alone, no height.
  const ViewFaces cap = prism_view_faces(seen(mesh, {300, 0, 0}), kTriangle, 60.0, pose);
  EXPECT_FALSE(cap.determines) << cap.note;
  EXPECT_GT(cap.counts[1], 0u);
  // Straight at the side on y = -10 (normal -z): one side, no outline.
  const ViewFaces side = prism_view_faces(seen(mesh, {0, 0, -300}), kTriangle, 60.0, pose);
  EXPECT_FALSE(side.determines) << side.note;
  // Obliquely past the cap onto that side: both.
  const ViewFaces both = prism_view_faces(seen(mesh, {200, 0, -200}), kTriangle, 60.0, pose);
  EXPECT_TRUE(both.determines) << both.note;
  EXPECT_GT(both.counts[1], 0u);
  EXPECT_GT(both.counts[2], 0u);  // side 0: corners 0 to 1, along y = -10
}

TEST(ViewFaces, TetrahedronNeedsTwoFaces) {
  const std::array<Eigen::Vector3d, 4> c = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(50, 0, 0),
                                            Eigen::Vector3d(0, 50, 0), Eigen::Vector3d(0, 0, 50)};
  const synth::SolidMesh mesh = synth::tetrahedron_mesh(c);
  // Below the face z = 0: that face alone.
  const ViewFaces one = tetrahedron_view_faces(seen(mesh, {10, 10, -300}), c);
  EXPECT_FALSE(one.determines) << one.note;
  EXPECT_EQ(one.counts[3], seen(mesh, {10, 10, -300}).size());  // face 3: opposite corner 3
  // Beyond the edge where the faces z = 0 and y = 0 meet: both.
  const ViewFaces two = tetrahedron_view_faces(seen(mesh, {20, -300, -300}), c);
  EXPECT_TRUE(two.determines) << two.note;
}

TEST(ViewFaces, FrustumNeedsItsSide) {
  const synth::Pose pose;  // larger end at the origin, the smaller one at x = 40
  const synth::SolidMesh mesh = synth::frustum_mesh(30.0, 15.0, 40.0, pose);
  const ViewFaces end = frustum_view_faces(seen(mesh, {-300, 0, 0}), 40.0, pose);
  EXPECT_FALSE(end.determines) << end.note;
  const ViewFaces side = frustum_view_faces(seen(mesh, {20, 0, 300}), 40.0, pose);
  EXPECT_TRUE(side.determines) << side.note;
}

}  // namespace
}  // namespace cloudshape::bench
