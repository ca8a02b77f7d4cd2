// The real files in shared/data/real (see SOURCES.md there), with the counts documented for them.
// Without the shared data folder: a failure under CI=true, a skip elsewhere (shared_data.hpp).
#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>

#include "io/cloud_reader.hpp"
#include "io/mesh_reader.hpp"
#include "io_test_support.hpp"
#include "shared_data.hpp"

namespace cloudshape::io {
namespace {

#define REQUIRE_REAL_FILE(var, relative)                                                      \
  const std::string var = ::cloudshape::testing::shared_data_path("real/" relative).string(); \
  CLOUDSHAPE_REQUIRE_SHARED_DATA(var)

TEST(IoRealData, MosdLearn0IsOrganisedWithNanPoints) {
  REQUIRE_REAL_FILE(path, "pcl/mOSD_learn0_boxes.pcd");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.format, "pcd-binary_compressed");
  EXPECT_EQ(cloud.points.size(), 182292u);
  EXPECT_EQ(cloud.non_finite_dropped, 307200u - 182292u);
}

TEST(IoRealData, MosdLearn33ReadsEveryPoint) {
  REQUIRE_REAL_FILE(path, "pcl/mOSD_learn33_cylinders.pcd");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.points.size() + cloud.non_finite_dropped, 307200u);
  EXPECT_GT(cloud.points.size(), 100000u);
}

TEST(IoRealData, MilkCarton) {
  REQUIRE_REAL_FILE(path, "pcl/milk.pcd");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.format, "pcd-binary_compressed");
  EXPECT_EQ(cloud.points.size(), 13704u);
  EXPECT_EQ(cloud.non_finite_dropped, 0u);
  // A tabletop object in metres: the carton's visible part is about 25 cm long.
  Eigen::AlignedBox3d box;
  for (const Point& p : cloud.points) box.extend(p);
  EXPECT_GT(box.sizes().maxCoeff(), 0.15);
  EXPECT_LT(box.sizes().maxCoeff(), 0.5);
}

TEST(IoRealData, TennisBallPlyAsCloud) {
  REQUIRE_REAL_FILE(path, "ycb/056_tennis_ball_google16k_nontextured.ply");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.format, "ply-ascii");
  EXPECT_EQ(cloud.points.size(), 8194u);
  // Declared "property float": read as the float the text denotes, as its binary form would be.
  EXPECT_EQ(cloud.points[0], Point(-0.017488999f, -0.057190999f, 0.017044f));
}

TEST(IoRealData, TennisBallPlyAsMesh) {
  REQUIRE_REAL_FILE(path, "ycb/056_tennis_ball_google16k_nontextured.ply");
  const Mesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 8194u);
  EXPECT_EQ(mesh.triangles.size(), 16384u);
}

TEST(IoRealData, SphereCalibLidarScan) {
  REQUIRE_REAL_FILE(path, "spherecalib/example3_L1_S1_lidar_sphere.xyz");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.format, "xyz");
  EXPECT_EQ(cloud.points.size(), 19232u);
  EXPECT_EQ(cloud.points[0], Point(0.015860459, 2.5963602, -0.69570559));
}

// Most YCB google_16k meshes have 8194 vertices; the two soup/coffee cans have fewer, so the
// expected vertex count is taken from the file's own "v" lines.
TEST(IoRealData, EveryYcbObjHasItsVerticesAnd16384Triangles) {
  REQUIRE_REAL_FILE(folder, "ycb");
  int meshes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".obj") continue;
    std::ifstream text(entry.path());
    std::size_t v_lines = 0;
    for (std::string line; std::getline(text, line);) v_lines += line.rfind("v ", 0) == 0;
    const Mesh mesh = read_mesh(entry.path().string());
    EXPECT_EQ(mesh.vertices.size(), v_lines) << entry.path();
    EXPECT_EQ(mesh.triangles.size(), 16384u) << entry.path();
    ++meshes;
  }
  EXPECT_EQ(meshes, 12);
}

TEST(IoRealData, CrackerBoxHas8194Vertices) {
  REQUIRE_REAL_FILE(path, "ycb/003_cracker_box_google16k.obj");
  EXPECT_EQ(read_mesh(path).vertices.size(), 8194u);
}

TEST(IoRealData, RavensCube) {
  REQUIRE_REAL_FILE(path, "ravens/kitting_03_cube.obj");
  const Mesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  Eigen::AlignedBox3d box;
  for (const Point& p : mesh.vertices) box.extend(p);
  EXPECT_EQ(box.sizes(), Eigen::Vector3d(20, 20, 20));
}

TEST(IoRealData, RavensPentagonalPrism) {
  REQUIRE_REAL_FILE(path, "ravens/kitting_07_pentagonal_prism.obj");
  const Mesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 10u);
  EXPECT_EQ(mesh.triangles.size(), 16u);
}

}  // namespace
}  // namespace cloudshape::io
