// End to end, as the outside evaluation makes its single views of real meshes:
// `cloudshape-synth mesh FILE --points 20000 --view X,Y,Z` then `cloudshape-recognize`. A box
// seen with one face at a grazing angle must come out as one box, with no stray objects made of
// hidden-surface slivers or cut off by a hole in the grazing face; a can seen from the side as
// one cylinder; a thin box with bulging faces as one box; an L or a T seen with a face its own arm
// half hides as one prism. Without shared/ beside the repository: a failure under CI=true, else a
// skip.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "process.hpp"
#include "shared_data.hpp"

namespace cloudshape {
namespace {

namespace fs = std::filesystem;

struct MeshView {
  std::string name;
  std::string file;  // under shared/data/real
  std::string camera;
  std::string shape;
  std::vector<std::pair<std::string, double>> dims;  // INTERFACE.md names, the file's unit
  double tolerance;                                  // per dimension, the file's unit
};

std::vector<MeshView> views() {
  return {
      // The +x face seen at a grazing angle: the z-buffer left its first 14 mm empty and the
      // recogniser found the box plus two coplanar strips.
      {"wood_block", "ycb/036_wood_block_google16k.obj", "0.1,-0.6,0.3", "box",
       {{"length", 0.2045}, {"width", 0.0884}, {"height", 0.0871}}, 0.008},
      // The CAD cube from the same direction: the z-buffer's slivers made four extra objects.
      {"ravens_cube", "ravens/kitting_03_cube.obj", "10,-60,30", "box", {{"length", 20}, {"width", 20}, {"height", 20}}, 0.2},
      // A can from the side, barely above its lid: the side breaks into strips flat enough to
      // pass for faces, and the cylinder fitted on the largest as a cap explained too little
      // (unknown) until the side's normals gave the axis. Truth: SOURCES.md, 32.95 x 101.9 mm.
      {"tomato_can_side", "ycb/005_tomato_soup_can_google16k.obj", "0.1,-0.6,0.3", "cylinder",
       {{"radius", 0.03295}, {"height", 0.1019}}, 0.003},
      // Seen from above one end, in the mesh's frame (its origin inside the brick): every point
      // beyond z = 0 and its top a support far on the origin's side, the view passed for a depth
      // camera's, and a face came apart from the rest (unknown and a box). Nearly none of its
      // surface faces the origin (segment.camera_facing_share). Truth: SOURCES.md, 74.9 x 50.6 x
      // 49.7 mm; measured 74.4 x 51.5 x 50.6.
      {"foam_brick", "ycb/061_foam_brick_google16k.obj", "0.5,0.3,0.4", "box",
       {{"length", 0.0749}, {"width", 0.0506}, {"height", 0.0497}}, 0.003},
      // The cracker box, thin (6.95 cm) and its large faces bulging: RANSAC cut a face into pieces
      // tilted 4-6 degrees, and the step test, judged across a piece's own plane, found the faces
      // square to it on both sides by more than a tenth of the thickness (unknown from three of
      // the four cameras of tools/real-views.sh). Truth: SOURCES.md, 210.6 x 159.4 x 69.5 mm.
      {"cracker_box", "ycb/003_cracker_box_google16k.obj", "0.5,0.3,0.4", "box",
       {{"length", 0.2106}, {"width", 0.1594}, {"height", 0.0695}}, 0.005},
      {"cracker_box_low", "ycb/003_cracker_box_google16k.obj", "0.6,-0.2,0.2", "box",
       {{"length", 0.2106}, {"width", 0.1594}, {"height", 0.0695}}, 0.005},
      // The CAD letters L and T (20 x 20, arms 6 wide, extruded 20), their cap and inner faces in
      // view: the other arm hides part of an inner face, whose points then filled 5% of the
      // side's rectangle (the L) and 13% (the T's), under the 60% that tells a prism's sides from
      // an octahedron's triangles, and the L passed for a box explaining 78% of its points, the T
      // for nothing. A side at a notch of an object alone is exempt (solve.prism_side_fill).
      {"ravens_letter_l", "ravens/kitting_15_letter_l.obj", "10,-60,30", "prism",
       {{"height", 20}, {"sides", 6}}, 0.2},
      {"ravens_letter_t", "ravens/kitting_05_letter_t.obj", "-40,20,50", "prism",
       {{"height", 20}, {"sides", 8}}, 0.2},
  };
}

// DISABLED (issue 10, left): seen from low, the can's lid is recessed 3 mm below its rim, the
// junction rim-lid is concave, and the segmentation cuts the lid off as a second object (a flat
// "cone"); the can itself is right (r 32.4 mm, h 101.2 mm). A concave junction parts patches
// under every join rule of convex_segments (the crease and sliver rules only part more, and
// hold in organized clouds); keeping the lid needs a test of how deep the step is.
std::vector<MeshView> recessed_lid_views() {
  return {{"tomato_can_low", "ycb/005_tomato_soup_can_google16k.obj", "0.6,-0.2,0.2", "cylinder",
           {{"radius", 0.03295}, {"height", 0.1019}}, 0.003}};
}

// Names the case in test listings instead of dumping its bytes.
void PrintTo(const MeshView& v, std::ostream* os) { *os << v.name; }

// cloudshape-recognize's JSON for `mesh` seen from `camera` (20 000 points, `seed`), as the outside
// evaluation makes it; null (and the test failed) where either tool fails.
nlohmann::json recognised_view(const fs::path& mesh, const std::string& camera,
                               const std::string& seed) {
  const fs::path cloud =
      fs::temp_directory_path() /
      ("cloudshape_mesh_view_" + mesh.stem().string() + "_" + std::to_string(getpid()) + ".pcd");
  const auto synth =
      testing::run_process({CLOUDSHAPE_SYNTH_BIN, "mesh", mesh.string(), "--points", "20000",
                            "--view", camera, "--seed", seed, "-o", cloud.string()});
  if (synth.exit_code != 0) {
    ADD_FAILURE() << synth.err;
    return nullptr;
  }
  const auto recognized = testing::run_process({CLOUDSHAPE_RECOGNIZE_BIN, cloud.string()});
  fs::remove(cloud);
  if (recognized.exit_code != 0) {
    ADD_FAILURE() << recognized.err;
    return nullptr;
  }
  return nlohmann::json::parse(recognized.out);
}

class MeshViewCli : public ::testing::TestWithParam<MeshView> {};

TEST_P(MeshViewCli, GivesOneSolidOfTheVisibleSize) {
  const MeshView& view = GetParam();
  const fs::path mesh = fs::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real" / view.file;
  CLOUDSHAPE_REQUIRE_SHARED_DATA(mesh);
  const nlohmann::json result = recognised_view(mesh, view.camera, "12");
  ASSERT_FALSE(result.is_null());
  EXPECT_EQ(result.at("points_in"), 20000);
  const auto& objects = result.at("objects");
  ASSERT_EQ(objects.size(), 1u) << objects.dump();
  ASSERT_EQ(objects[0].at("shape"), view.shape) << objects[0].dump();
  const auto& d = objects[0].at("dimensions");
  for (const auto& [name, truth] : view.dims) {
    ASSERT_TRUE(d.contains(name)) << d.dump();
    EXPECT_NEAR(d.at(name).get<double>(), truth, view.tolerance) << name;
  }
}

// A real box's bulging face and a can's recessed lid, each seen from above (the cracker box from
// 13 degrees up, its front face bulging 5 mm; the tuna can from 71 degrees, its lid's dish a
// segment of its own): a cone 0.32 m and 0.10 m wide and 7-10 mm tall fitted each gentle dome,
// its base rim far beyond the points (they reached 0.58 and 0.69 of its radius), and was named at
// confidence 0.59 and 0.68. No cone or frustum stands where its points stop short of its rim
// (solve.tapered_min_rim_reach); unknown is an honest answer here.
TEST(MeshViewCliGentleDome, IsNoCone) {
  const std::vector<std::pair<std::string, std::pair<std::string, std::string>>> cases = {
      {"ycb/003_cracker_box_google16k.obj", {"0.578,-0.087,0.135", "12"}},
      {"ycb/007_tuna_fish_can_google16k.obj", {"-0.132,-0.136,0.569", "29"}}};
  for (const auto& [file, view] : cases) {
    const fs::path mesh = fs::path(CLOUDSHAPE_SHARED_DATA_DIR) / "real" / file;
    CLOUDSHAPE_REQUIRE_SHARED_DATA(mesh);
    const nlohmann::json result = recognised_view(mesh, view.first, view.second);
    ASSERT_FALSE(result.is_null()) << file;
    const auto& objects = result.at("objects");
    ASSERT_FALSE(objects.empty()) << file;
    for (const auto& o : objects) {
      EXPECT_NE(o.at("shape"), "cone") << file << ": " << o.dump();
      EXPECT_NE(o.at("shape"), "frustum") << file << ": " << o.dump();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RealMeshes, MeshViewCli, ::testing::ValuesIn(views()),
                         [](const auto& info) { return info.param.name; });
INSTANTIATE_TEST_SUITE_P(DISABLED_RecessedLid, MeshViewCli, ::testing::ValuesIn(recessed_lid_views()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace cloudshape
