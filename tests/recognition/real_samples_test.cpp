// The real samples of shared/data/real (SOURCES.md): YCB scans sampled at 20k points and the
// ravens CAD solids. Tolerance: 8% of the face-to-face value (CAD: 1%), SOURCES.md's
// relative criterion without its 5 mm floor, which let the small objects (a 25 mm cube, a
// 21 mm radius) be 15-24% off. Without shared/ beside the repository: a failure under
// CI=true, a skip elsewhere (shared_data.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <random>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "io/mesh_reader.hpp"
#include "pipeline/recognize.hpp"
#include "shared_data.hpp"
#include "synth/mesh_sampling.hpp"

namespace cloudshape {
namespace {

struct Sample {
  std::string file;
  std::string shape;
  std::vector<double> dims;  // INTERFACE.md order, in the file's unit
  double scale_to_mm;        // YCB files are in metres
  bool cad;
};

const std::vector<Sample>& samples() {
  static const std::vector<Sample> all = {
      {"ycb/003_cracker_box_google16k.obj", "box", {210.6, 159.4, 69.5}, 1000, false},
      {"ycb/004_sugar_box_google16k.obj", "box", {173.4, 89.7, 43.6}, 1000, false},
      {"ycb/009_gelatin_box_google16k.obj", "box", {87.1, 71.2, 28.7}, 1000, false},
      {"ycb/061_foam_brick_google16k.obj", "box", {74.9, 50.6, 49.7}, 1000, false},
      {"ycb/036_wood_block_google16k.obj", "box", {204.5, 88.4, 87.1}, 1000, false},
      {"ycb/077_rubiks_cube_google16k.obj", "box", {56.9, 56.8, 56.5}, 1000, false},
      {"ycb/070-b_colored_wood_blocks_google16k.obj", "box", {25.4, 25.4, 25.3}, 1000, false},
      {"ycb/002_master_chef_can_google16k.obj", "cylinder", {99.7 / 2, 140.2}, 1000, false},
      {"ycb/005_tomato_soup_can_google16k.obj", "cylinder", {65.9 / 2, 101.9}, 1000, false},
      {"ycb/007_tuna_fish_can_google16k.obj", "cylinder", {84.0 / 2, 33.5}, 1000, false},
      {"ycb/055_baseball_google16k.obj", "sphere", {73.1 / 2}, 1000, false},
      {"ycb/056_tennis_ball_google16k_nontextured.ply", "sphere", {66.8 / 2}, 1000, false},
      {"ycb/058_golf_ball_google16k.obj", "sphere", {42.5 / 2}, 1000, false},
      {"ravens/kitting_03_cube.obj", "box", {20, 20, 20}, 1, true},
      {"ravens/kitting_07_pentagonal_prism.obj", "pentagonal_prism", {11.775, 20.032}, 1, true},
  };
  return all;
}

// The mesh sampled whole at 20k points (seed 1) and recognised with the shipped configuration.
pipeline::RecognitionResult recognize_sampled_mesh(const std::filesystem::path& path, const std::string& source) {
  const io::Mesh mesh = io::read_mesh(path.string());
  std::mt19937_64 rng(1);
  const PointList cloud = synth::sample_mesh_surface(mesh.vertices, mesh.triangles, 20000, rng);
  return pipeline::recognize_cloud(cloud, config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML), source);
}

// Names the sample in test listings instead of dumping its bytes.
void PrintTo(const Sample& s, std::ostream* os) { *os << s.file; }

class RealSample : public ::testing::TestWithParam<Sample> {};

TEST_P(RealSample, ShapeAndDimensionsWithinSourcesTolerance) {
  const Sample& s = GetParam();
  const std::filesystem::path path = std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real" / s.file;
  CLOUDSHAPE_REQUIRE_SHARED_DATA(path);
  const auto result = recognize_sampled_mesh(path, s.file);
  ASSERT_EQ(result.objects.size(), 1u);
  const auto& got = result.objects.front();
  // One Markdown row per sample: docs/performance.md's real-data table is this output.
  std::string reported, truth;
  for (std::size_t d = 0; d < got.dimensions.size(); ++d)
    reported += (d ? " x " : "") + std::to_string(got.dimensions[d].second * s.scale_to_mm).substr(0, 5);
  for (std::size_t d = 0; d < s.dims.size(); ++d)
    truth += (d ? " x " : "") + std::to_string(s.dims[d]).substr(0, 5);
  std::printf("| %s | %s | %s | %s | %s | %.2f |\n", s.file.c_str(), s.shape.c_str(), truth.c_str(),
              got.shape.c_str(), reported.c_str(), got.confidence);
  ASSERT_EQ(got.shape, s.shape) << got.reason;
  ASSERT_EQ(got.dimensions.size(), s.dims.size());
  for (std::size_t d = 0; d < s.dims.size(); ++d) {
    const double mm = got.dimensions[d].second * s.scale_to_mm;
    const double tol = (s.cad ? 0.01 : 0.08) * s.dims[d];
    EXPECT_NEAR(mm, s.dims[d], tol) << got.dimensions[d].first;
  }
}

INSTANTIATE_TEST_SUITE_P(SharedData, RealSample, ::testing::ValuesIn(samples()),
                         [](const auto& info) {
                           std::string name = std::filesystem::path(info.param.file).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// The ravens CAD profiles beyond the six (SOURCES.md): right prisms with non-convex outlines,
// sampled whole at 20k points. Right: `prism`, the outline's corner count, the extrusion within
// 1% (CAD); the area within 2% where SOURCES.md's arm widths give it (the star's tips vary).
struct ProfileSample {
  std::string file;
  std::size_t sides;
  double height;
  double area;  // < 0: not given
};

void PrintTo(const ProfileSample& s, std::ostream* os) { *os << s.file; }

class RavensProfile : public ::testing::TestWithParam<ProfileSample> {};

TEST_P(RavensProfile, IsAPrismWithItsSidesAndHeight) {
  const ProfileSample& s = GetParam();
  const std::filesystem::path path = std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real" / s.file;
  CLOUDSHAPE_REQUIRE_SHARED_DATA(path);
  const auto result = recognize_sampled_mesh(path, s.file);
  ASSERT_EQ(result.objects.size(), 1u);
  const auto& got = result.objects.front();
  ASSERT_EQ(got.shape, "prism") << got.reason;
  EXPECT_EQ(got.polygon.size(), s.sides);
  ASSERT_FALSE(got.dimensions.empty());
  EXPECT_EQ(got.dimensions[0].first, "height");
  EXPECT_NEAR(got.dimensions[0].second, s.height, 0.01 * s.height);
  if (s.area > 0) {
    double twice = 0.0;
    for (std::size_t i = 0; i < got.polygon.size(); ++i) {
      const auto& a = got.polygon[i];
      const auto& b = got.polygon[(i + 1) % got.polygon.size()];
      twice += a.x() * b.y() - a.y() * b.x();
    }
    EXPECT_GT(twice, 0.0) << "counter-clockwise";
    EXPECT_NEAR(0.5 * twice, s.area, 0.02 * s.area);
  }
}

INSTANTIATE_TEST_SUITE_P(SharedData, RavensProfile,
                         ::testing::Values(ProfileSample{"ravens/kitting_04_plus.obj", 12, 20.0, 20 * 10 * 2 - 10 * 10},
                                           ProfileSample{"ravens/kitting_05_letter_t.obj", 8, 20.0, 6 * 20 + 6 * 14},
                                           ProfileSample{"ravens/kitting_10_star.obj", 10, 20.0, -1},
                                           ProfileSample{"ravens/kitting_15_letter_l.obj", 6, 20.0, 6 * 20 + 6 * 14}),
                         [](const auto& info) {
                           std::string name = std::filesystem::path(info.param.file).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(RealScan, MilkCartonSingleViewIsABox) {
  const std::filesystem::path path = std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real/pcl/milk.pcd";
  CLOUDSHAPE_REQUIRE_SHARED_DATA(path);
  const auto result = pipeline::recognize_cloud(io::read_cloud(path.string()).points,
                                                config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML), "milk");
  ASSERT_EQ(result.objects.size(), 1u);
  EXPECT_EQ(result.objects.front().shape, "box");
}

// Table-top Kinect scenes (SOURCES.md: 2 boxes; 5 cylindrical objects, some in two labelled
// parts), organized as the camera gave them. Without the table removed each came out as one big
// box. Of the five cylindrical objects two are bowls seen over their rims (a sphere-like inside
// behind a depth jump): three come out as cylinders (cloudshape-bench --scenes, learn33).
TEST(RealScan, TableTopScenesGiveTheObjectsOnTheTable) {
  const auto dir = std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real/pcl";
  const auto boxes_path = dir / "mOSD_learn0_boxes.pcd", cylinders_path = dir / "mOSD_learn33_cylinders.pcd";
  CLOUDSHAPE_REQUIRE_SHARED_DATA(boxes_path);
  CLOUDSHAPE_REQUIRE_SHARED_DATA(cylinders_path);
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  const io::CloudFile boxes_file = io::read_cloud(boxes_path.string());
  const auto boxes = pipeline::recognize_cloud(boxes_file.points, boxes_file.grid, cfg, "boxes");
  ASSERT_EQ(boxes.objects.size(), 2u);
  for (const auto& o : boxes.objects) {
    EXPECT_EQ(o.shape, "box");
    EXPECT_LT(o.dimensions.front().second, 0.4);  // objects, not the ~1.3 m table
  }
  const io::CloudFile cylinders_file = io::read_cloud(cylinders_path.string());
  const auto cylinders = pipeline::recognize_cloud(cylinders_file.points, cylinders_file.grid, cfg, "cylinders");
  int found = 0;
  for (const auto& o : cylinders.objects) found += o.shape == "cylinder" ? 1 : 0;
  EXPECT_GE(found, 3) << cylinders.objects.size() << " objects";
  EXPECT_LE(cylinders.objects.size(), 7u);
}

// The SphereCalib lidar frame (SOURCES.md), recognised with the shipped configuration.
std::filesystem::path spherecalib_path() {
  return std::filesystem::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real/spherecalib/example3_L1_S1_lidar_sphere.xyz";
}
pipeline::RecognitionResult recognise_spherecalib() {
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  return pipeline::recognize_cloud(io::read_cloud(spherecalib_path().string()).points, cfg, "spherecalib");
}
const Eigen::Vector3d kSphereCalibCentre(1.723, 2.471, 0.009);

// The SphereCalib lidar scan (SOURCES.md): a 0.293 m sphere, centre (1.723, 2.471, 0.009) m,
// 275 points on ~11 scan rings, in a 38 x 28 x 7.5 m scene of ground and walls: the sphere is
// one of the objects, recognised from its own points at its own resolution (the frame's sensor
// at the origin, its walls and ground structure seen from inside, the rest re-gridded finer).
// Tolerance (the scene issue's acceptance): radius within 5%, centre within 5 cm, and no other
// object but unknown within two radii of the centre.
TEST(RealScan, LidarCalibrationSphereAmongGroundAndWalls) {
  CLOUDSHAPE_REQUIRE_SHARED_DATA(spherecalib_path());
  const auto result = recognise_spherecalib();
  const Eigen::Vector3d centre = kSphereCalibCentre;
  const auto nearest = std::min_element(result.objects.begin(), result.objects.end(), [&](const auto& a, const auto& b) {
    return (a.center - centre).norm() < (b.center - centre).norm();
  });
  ASSERT_NE(nearest, result.objects.end());
  EXPECT_EQ(nearest->shape, "sphere");
  ASSERT_FALSE(nearest->dimensions.empty());
  EXPECT_NEAR(nearest->dimensions.front().second, 0.293, 0.05 * 0.293);
  EXPECT_LT((nearest->center - centre).norm(), 0.05);
  for (const auto& o : result.objects) {
    if (&o == &*nearest || o.shape == "unknown") continue;
    EXPECT_GT((o.center - centre).norm(), 2.0 * 0.293) << o.shape << " claimed beside the sphere";
  }
}

// The frame's other segments are strips of ground rings and walls the structure left, or sparse
// clutter: those on fewer beams than a solid needs (segment.scan_object_min_beams) or mostly within
// a structure plane's band (segment.scan_leftover_share) are dropped, and a solid that leaves its
// points scattered by more than solve.scan_noise_ratio times their noise along the rings is no
// answer, an object on fewer beams than solve.solid_min_scan_lines (5) is tried as a sphere
// only, and a solid the sensor saw through is no answer either (solve.free_space_max_share: two
// cylinders of wall strips, 56-61% of their crossing rays returning from beyond them), so few named
// solids remain beside the sphere (measured: 1, a sphere; 3 without the free-space test, 8 while
// objects on three and four beams were fitted any solid; bound 2: a margin of 1 for other RANSAC
// draws). Spheres 1.8 and 5.6 m from the calibration sphere, their points 6.5 and 7.2 times
// their noise from them (the calibration sphere's: 1.4), are no answer: no sphere but that one is
// named within 5 m of it.
TEST(RealScan, LidarFrameNamesFewSolidsBesideTheSphere) {
  CLOUDSHAPE_REQUIRE_SHARED_DATA(spherecalib_path());
  const auto result = recognise_spherecalib();
  const Eigen::Vector3d centre = kSphereCalibCentre;
  std::size_t spheres_there = 0, named_elsewhere = 0;
  for (const auto& o : result.objects) {
    if (o.shape == "unknown") continue;
    if ((o.center - centre).norm() < 0.05 && o.shape == "sphere") {
      ++spheres_there;
    } else {
      ++named_elsewhere;
    }
  }
  EXPECT_EQ(spheres_there, 1u);
  EXPECT_LE(named_elsewhere, 2u);
  for (const auto& o : result.objects) {
    const double off = (o.center - centre).norm();
    if (o.shape == "sphere" && off >= 0.05) {
      EXPECT_GT(off, 5.0) << "a sphere " << off << " m from the calibration sphere";
    }
  }
}

}  // namespace
}  // namespace cloudshape
