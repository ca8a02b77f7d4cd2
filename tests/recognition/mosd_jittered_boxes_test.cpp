// Real Kinect boxes moved by a twentieth of their point spacing (0.1 mm, far below the sensor's
// noise) stay boxes: a prism outline placed on a cap's ragged border does not outbid the box's
// faces, nor does a face RANSAC cut in pieces fail the box.
#include <gtest/gtest.h>

#include <string>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "mosd_frames.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape {
namespace {

// learn3, learn15 and learn18 (boxes apart, three boxes in a row, stacked boxes), each under four
// seeded jitters of 0.05 of its point spacing: without solve.guessed_side_cost (0) learn3's box
// under seed 4 is a prism whose sides but one were traced on its top's border, explaining a few
// per cent more points than the box's faces; with the bench's own jitter seeds 3 of 135 runs of
// the 45 frames named a box so. None may now.
TEST(MosdJitteredBoxes, NoBoxIsAPrism) {
  if (mosd::data_missing()) GTEST_SKIP() << mosd::kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  for (int frame : {3, 15, 18}) {
    const io::CloudFile file = io::read_cloud(mosd::frame_path(frame));
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const auto result = pipeline::recognize_cloud(
          mosd::jittered(file.points, 0.05, seed), file.grid, cfg, "learn" + std::to_string(frame));
      for (const auto& o : result.objects)
        EXPECT_NE(o.shape, "prism") << "learn" << frame << ", seed " << seed;
    }
  }
}

// The box frames learn0-16 under the three jitters `cloudshape-bench --scenes --jitter 0.05` gives
// them (seed 1000003 * frame + run): the labelled boxes are named boxes in at least 110 of the 114
// runs (measured 112; the bench's boxes row). RANSAC cuts a bulging face into pieces a few
// millimetres apart, and a piece cut across the face failed the box's rectangle test alone: 108
// before the pieces were judged as one face.
TEST(MosdJitteredBoxes, BoxesOfTheBoxFramesAreBoxes) {
  if (mosd::data_missing()) GTEST_SKIP() << mosd::kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  int boxes = 0, runs = 0;
  for (int frame = 0; frame <= 16; ++frame) {
    const io::CloudFile file = io::read_cloud(mosd::frame_path(frame));
    for (std::uint64_t run = 0; run < 3; ++run) {
      const auto result = pipeline::recognize_cloud(
          mosd::jittered(file.points, 0.05, 1000003ull * static_cast<std::uint64_t>(frame) + run),
          file.grid, cfg, "learn" + std::to_string(frame));
      for (const auto& [object, shape] : mosd::shapes_of_objects(file, result)) {
        ++runs;
        boxes += shape == "box";
      }
    }
  }
  EXPECT_EQ(runs, 114);
  EXPECT_GE(boxes, 110) << "of " << runs;
}

}  // namespace
}  // namespace cloudshape
