// Exact mesh visibility on a box mesh, from a corner direction down to faces seen 85 degrees off
// their normal: no point of a hidden face is kept, every point of a visible face is, and a
// single view sampled to n points covers each visible face evenly, without gaps.
#include "box_mesh.hpp"
#include "synth/mesh_visibility.hpp"
#include "synth/visibility.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <ostream>
#include <random>

namespace cloudshape::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
const Eigen::AlignedBox3d kBox(Eigen::Vector3d(-1.0, -0.6, -0.4), Eigen::Vector3d(1.0, 0.6, 0.4));

struct View {
  const char* name;
  Eigen::Vector3d camera;
};

// A camera 6 units from the centre whose direction is `off_normal` degrees from +z and 30
// degrees round from +x: the top face is seen at that angle, the +x and +y faces too.
Eigen::Vector3d camera_off_top_normal(double off_normal) {
  const double t = off_normal * kPi / 180.0, p = 30.0 * kPi / 180.0;
  return 6.0 * Eigen::Vector3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

std::vector<View> views() {
  return {{"corner", Eigen::Vector3d(4, 4, 4)},
          {"wood_block_direction", 10.0 * Eigen::Vector3d(0.13, -0.6, 0.3)},
          {"top_60deg", camera_off_top_normal(60)},
          {"top_75deg", camera_off_top_normal(75)},
          {"top_85deg", camera_off_top_normal(85)}};
}

// Face index 2 * axis + side (side 1 = the max face), or -1 when p is on no face.
int face_of(const Eigen::Vector3d& p) {
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(p[axis] - kBox.max()[axis]) < 1e-9) return 2 * axis + 1;
    if (std::abs(p[axis] - kBox.min()[axis]) < 1e-9) return 2 * axis;
  }
  return -1;
}

// A face of a convex solid is seen whole when the camera is beyond its plane, else not at all.
bool face_visible(int face, const Eigen::Vector3d& camera) {
  const int axis = face / 2;
  return face % 2 ? camera[axis] > kBox.max()[axis] : camera[axis] < kBox.min()[axis];
}

double face_area(int face) {
  const int axis = face / 2;
  return kBox.sizes()[(axis + 1) % 3] * kBox.sizes()[(axis + 2) % 3];
}

test::TriangleMesh box_mesh() {
  test::TriangleMesh mesh;
  test::add_box(mesh, kBox, 8);
  return mesh;
}

// Names the case in test listings instead of dumping its bytes.
void PrintTo(const View& c, std::ostream* os) { *os << c.name; }

class MeshVisibilityBox : public ::testing::TestWithParam<View> {};

TEST_P(MeshVisibilityBox, KeepsExactlyThePointsOfTheFacesTurnedToTheCamera) {
  const test::TriangleMesh mesh = box_mesh();
  std::mt19937_64 rng(71);
  const PointList points = sample_mesh_surface(mesh.vertices, mesh.triangles, 30000, rng);
  const Eigen::Vector3d camera = GetParam().camera;
  std::size_t expected = 0;
  for (const auto& p : points) expected += face_visible(face_of(p), camera) ? 1 : 0;
  const PointList seen = MeshVisibility(mesh.vertices, mesh.triangles).visible(points, camera);
  EXPECT_EQ(seen.size(), expected);
  for (const auto& p : seen)
    ASSERT_TRUE(face_visible(face_of(p), camera)) << "hidden-face point kept: " << p.transpose();
}

TEST_P(MeshVisibilityBox, ASingleViewCoversEachVisibleFaceEvenly) {
  const test::TriangleMesh mesh = box_mesh();
  const MeshVisibility visibility(mesh.vertices, mesh.triangles);
  const Eigen::Vector3d camera = GetParam().camera;
  std::mt19937_64 rng(72);
  const std::size_t n = 20000;
  const PointList seen = sample_visible(
      [&](std::size_t m) { return sample_mesh_surface(mesh.vertices, mesh.triangles, m, rng); },
      [&](const PointList& points) { return visibility.visible(points, camera); }, n, rng);
  ASSERT_EQ(seen.size(), n);

  double visible_area = 0.0;
  for (int face = 0; face < 6; ++face) visible_area += face_visible(face, camera) ? face_area(face) : 0.0;
  std::array<std::size_t, 6> count{};
  for (const auto& p : seen) {
    const int face = face_of(p);
    ASSERT_TRUE(face >= 0 && face_visible(face, camera)) << p.transpose();
    ++count[face];
  }
  const double spacing = std::sqrt(visible_area / n);
  for (int face = 0; face < 6; ++face) {
    if (!face_visible(face, camera)) continue;
    // Uniform density: each face's share is its share of the visible area (binomial sd < 0.004).
    EXPECT_NEAR(double(count[face]) / n, face_area(face) / visible_area, 0.015) << "face " << face;
    // No gaps: every spot of the face has a point within 4 spacings (a uniform sample of 20000
    // leaves its largest empty disc about 2 spacings across).
    const int axis = face / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    double worst = 0.0;
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; j <= 40; ++j) {
        Eigen::Vector3d probe;
        probe[axis] = face % 2 ? kBox.max()[axis] : kBox.min()[axis];
        probe[u] = kBox.min()[u] + kBox.sizes()[u] * i / 40.0;
        probe[v] = kBox.min()[v] + kBox.sizes()[v] * j / 40.0;
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto& p : seen) nearest = std::min(nearest, (p - probe).squaredNorm());
        worst = std::max(worst, std::sqrt(nearest));
      }
    EXPECT_LT(worst, 4.0 * spacing) << "face " << face << ": a gap of " << worst / spacing
                                    << " point spacings";
  }
}

INSTANTIATE_TEST_SUITE_P(Views, MeshVisibilityBox, ::testing::ValuesIn(views()),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace cloudshape::synth
