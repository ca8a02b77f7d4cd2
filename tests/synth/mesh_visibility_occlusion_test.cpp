// Exact mesh visibility where the mesh hides part of itself: an L-shaped solid (two boxes
// sharing a face, so the shared faces lie inside) and two boxes one behind the other. Every
// sampled point must be kept exactly when its line of sight stays out of the solid.
#include "box_mesh.hpp"
#include "synth/mesh_visibility.hpp"

#include <gtest/gtest.h>

#include <ostream>
#include <random>
#include <stdexcept>

namespace cloudshape::synth {
namespace {

using Box = Eigen::AlignedBox3d;
using Eigen::Vector3d;

struct Scene {
  const char* name;
  std::vector<Box> boxes;
  Vector3d camera;
  double min_hidden_share;  // of the faces that look at the camera: occlusion really happens
};

std::vector<Scene> scenes() {
  const Box foot(Vector3d(0, 0, 0), Vector3d(2, 1, 1)), leg(Vector3d(0, 0, 1), Vector3d(1, 1, 2));
  const Box front(Vector3d(-0.5, -0.5, 1), Vector3d(0.5, 0.5, 2));
  const Box back(Vector3d(-1.5, -1.5, -1), Vector3d(1.5, 1.5, 0));
  return {
      // From +x and above, the leg's +x face shades part of the foot's top beside it.
      {"l_shape_inner_corner", {foot, leg}, Vector3d(6, -2, 3), 0.02},
      // From the -x side and above the leg hides part of the foot's top behind it.
      {"l_shape_from_behind", {foot, leg}, Vector3d(-4, 3, 6), 0.02},
      {"box_in_front_of_box", {front, back}, Vector3d(1.0, 0.7, 8), 0.05},
      {"box_in_front_of_box_oblique", {front, back}, Vector3d(5, -4, 6), 0.02},
  };
}

// Names the case in test listings instead of dumping its bytes.
void PrintTo(const Scene& c, std::ostream* os) { *os << c.name; }

class MeshVisibilityOcclusion : public ::testing::TestWithParam<Scene> {};

TEST_P(MeshVisibilityOcclusion, HidesExactlyWhatTheSolidCovers) {
  const Scene& scene = GetParam();
  test::TriangleMesh mesh;
  for (const auto& box : scene.boxes) test::add_box(mesh, box, 6);
  std::mt19937_64 rng(81);
  const PointList points = sample_mesh_surface(mesh.vertices, mesh.triangles, 40000, rng);
  const MeshVisibility visibility(mesh.vertices, mesh.triangles);

  std::size_t wrongly_kept = 0, wrongly_hidden = 0, truly_visible = 0, shaded = 0;
  for (const auto& p : points) {
    const bool hidden = test::sight_line_blocked(scene.boxes, scene.camera, p);
    const bool kept = visibility.visible({p}, scene.camera).size() == 1;
    truly_visible += hidden ? 0 : 1;
    wrongly_kept += hidden && kept ? 1 : 0;
    wrongly_hidden += !hidden && !kept ? 1 : 0;
    // Shaded: on a face that looks at the camera (hidden only by another part of the solid).
    const Vector3d towards = scene.camera - p;
    bool faces_camera = false;
    for (const auto& box : scene.boxes)
      for (int a = 0; a < 3; ++a)
        faces_camera |= (std::abs(p[a] - box.max()[a]) < 1e-12 && towards[a] > 0) ||
                        (std::abs(p[a] - box.min()[a]) < 1e-12 && towards[a] < 0);
    shaded += hidden && faces_camera ? 1 : 0;
  }
  EXPECT_EQ(wrongly_kept, 0u);
  EXPECT_EQ(wrongly_hidden, 0u);
  EXPECT_GT(truly_visible, points.size() / 10);
  EXPECT_GT(double(shaded) / points.size(), scene.min_hidden_share) << "the scene shows no occlusion";
}

INSTANTIATE_TEST_SUITE_P(Scenes, MeshVisibilityOcclusion, ::testing::ValuesIn(scenes()),
                         [](const auto& info) { return std::string(info.param.name); });

// Bad input: a triangle naming a missing vertex is refused.
TEST(MeshVisibility, RejectsBadIndicesAndASingleTriangleHides) {
  const PointList v{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(MeshVisibility(v, {{0, 1, 4}}), std::invalid_argument);
  // One triangle across the line of sight hides the point behind it, not the one beside it.
  const MeshVisibility wall(v, {{0, 1, 3}});
  EXPECT_TRUE(wall.visible({Vector3d(0.2, 0.2, -1)}, Vector3d(0.2, 0.2, 1)).empty());
  EXPECT_EQ(wall.visible({Vector3d(0.8, 0.8, -1)}, Vector3d(0.8, 0.8, 1)).size(), 1u);
}

}  // namespace
}  // namespace cloudshape::synth
