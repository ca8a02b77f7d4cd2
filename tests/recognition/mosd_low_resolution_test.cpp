// Real Kinect frames at 320 x 240 (every other pixel of every other row, as a camera run at that
// resolution gives them, `cloudshape-bench --scenes --decimate 2`): cans stay cylinders.
#include <gtest/gtest.h>

#include <string>

#include "config/pipeline_config.hpp"
#include "io/cloud_decimate.hpp"
#include "io/cloud_reader.hpp"
#include "mosd_frames.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape {
namespace {

// learn39 and learn44, object 4 of each: a can about 0.8 m off seen over part of its arc. In
// learn44, 960 points at this resolution: its faces and key-points gave a cylinder explaining 65%
// of them and a sphere 72%, and the sphere was named (confidence 0.68); the second chance, a
// cylinder fitted to the side's normals and points alone, was tried only where nothing explained
// half the points. It is now tried where the sphere or cylinder chosen explains less than
// solve.second_chance_round_below (0.9), and explains 99% of that can. Both were spheres before;
// as read (640 x 480) both frames were right before and are still.
TEST(MosdLowResolution, ACanSeenOverPartOfItsArcIsNoBall) {
  if (mosd::data_missing()) GTEST_SKIP() << mosd::kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  for (int frame : {39, 44}) {
    const io::CloudFile file = io::decimated(io::read_cloud(mosd::frame_path(frame)), 2);
    ASSERT_EQ(file.grid.width, 320u);
    ASSERT_EQ(file.grid.height, 240u);
    const auto result =
        pipeline::recognize_cloud(file.points, file.grid, cfg, "learn" + std::to_string(frame));
    const auto shapes = mosd::shapes_of_objects(file, result);
    ASSERT_EQ(shapes.count(4), 1u) << "learn" << frame;
    EXPECT_EQ(shapes.at(4), "cylinder") << "learn" << frame;
    for (const auto& [object, shape] : shapes)
      EXPECT_EQ(shape, "cylinder") << "learn" << frame << " object " << object;
  }
}

}  // namespace
}  // namespace cloudshape
