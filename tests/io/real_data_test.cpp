// The real files in shared/data/real (see SOURCES.md there), with the counts documented for them.
// Skipped when the shared data folder is not present.
#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>

#include "io/cloud_reader.hpp"
#include "io/mesh_reader.hpp"
#include "io_test_support.hpp"

namespace cloudshape::io {
namespace {

std::string real(const std::string& relative) {
  const std::string path = test::shared_data("real/" + relative);
  if (!std::filesystem::exists(path)) return {};
  return path;
}

#define REAL_FILE_OR_SKIP(var, relative)                        \
  const std::string var = real(relative);                       \
  if ((var).empty()) GTEST_SKIP() << "no shared data: " << (relative)

TEST(IoRealData, MosdLearn0IsOrganisedWithNanPoints) {
  REAL_FILE_OR_SKIP(path, "pcl/mOSD_learn0_boxes.pcd");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.format, "pcd-binary_compressed");
  EXPECT_EQ(cloud.points.size(), 182292u);
  EXPECT_EQ(cloud.non_finite_dropped, 307200u - 182292u);
}

TEST(IoRealData, MosdLearn33ReadsEveryPoint) {
  REAL_FILE_OR_SKIP(path, "pcl/mOSD_learn33_cylinders.pcd");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.points.size() + cloud.non_finite_dropped, 307200u);
  EXPECT_GT(cloud.points.size(), 100000u);
}

TEST(IoRealData, MilkCarton) {
  REAL_FILE_OR_SKIP(path, "pcl/milk.pcd");
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
  REAL_FILE_OR_SKIP(path, "ycb/056_tennis_ball_google16k_nontextured.ply");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.format, "ply-ascii");
  EXPECT_EQ(cloud.points.size(), 8194u);
  // Declared "property float": read as the float the text denotes, as its binary form would be.
  EXPECT_EQ(cloud.points[0], Point(-0.017488999f, -0.057190999f, 0.017044f));
}

TEST(IoRealData, TennisBallPlyAsMesh) {
  REAL_FILE_OR_SKIP(path, "ycb/056_tennis_ball_google16k_nontextured.ply");
  const Mesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 8194u);
  EXPECT_EQ(mesh.triangles.size(), 16384u);
}

TEST(IoRealData, SphereCalibLidarScan) {
  REAL_FILE_OR_SKIP(path, "spherecalib/example3_L1_S1_lidar_sphere.xyz");
  const CloudFile cloud = read_cloud(path);
  EXPECT_EQ(cloud.format, "xyz");
  EXPECT_EQ(cloud.points.size(), 19232u);
  EXPECT_EQ(cloud.points[0], Point(0.015860459, 2.5963602, -0.69570559));
}

// Most YCB google_16k meshes have 8194 vertices; the two soup/coffee cans have fewer, so the
// expected vertex count is taken from the file's own "v" lines.
TEST(IoRealData, EveryYcbObjHasItsVerticesAnd16384Triangles) {
  const std::string folder = real("ycb");
  if (folder.empty()) GTEST_SKIP() << "no shared data";
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
  REAL_FILE_OR_SKIP(path, "ycb/003_cracker_box_google16k.obj");
  EXPECT_EQ(read_mesh(path).vertices.size(), 8194u);
}

TEST(IoRealData, RavensCube) {
  REAL_FILE_OR_SKIP(path, "ravens/kitting_03_cube.obj");
  const Mesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  Eigen::AlignedBox3d box;
  for (const Point& p : mesh.vertices) box.extend(p);
  EXPECT_EQ(box.sizes(), Eigen::Vector3d(20, 20, 20));
}

TEST(IoRealData, RavensPentagonalPrism) {
  REAL_FILE_OR_SKIP(path, "ravens/kitting_07_pentagonal_prism.obj");
  const Mesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 10u);
  EXPECT_EQ(mesh.triangles.size(), 16u);
}

}  // namespace
}  // namespace cloudshape::io
