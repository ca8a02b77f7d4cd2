// Real Kinect frames exported without their pixel grid (as a PLY or XYZ export of the frame has
// them): the grid comes back from the points' directions, and the frames are recognised as read.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "mosd_frames.hpp"
#include "pipeline/recognize.hpp"
#include "segment/pinhole_grid.hpp"

namespace cloudshape {
namespace {

// Every point's pixel is the frame's own, moved by one offset (the first row and column seen).
TEST(MosdWithoutGrid, EveryPixelComesBack) {
  if (mosd::data_missing()) GTEST_SKIP() << mosd::kDir << " not present";
  for (int frame : {0, 20, 33}) {
    const io::CloudFile file = io::read_cloud(mosd::frame_path(frame));
    ASSERT_TRUE(file.grid.organized());
    const auto grid = segment::pinhole_grid(file.points);
    ASSERT_TRUE(grid.has_value()) << "learn" << frame;
    const std::size_t w = file.grid.width;
    std::size_t row0 = file.grid.height, column0 = w;
    for (std::uint32_t p : file.grid.pixel) {
      row0 = std::min<std::size_t>(row0, p / w);
      column0 = std::min<std::size_t>(column0, p % w);
    }
    std::size_t moved = 0;
    for (std::size_t i = 0; i < file.points.size(); ++i) {
      const std::size_t row = file.grid.pixel[i] / w - row0,
                        column = file.grid.pixel[i] % w - column0;
      moved += grid->pixel[i] == row * grid->width + column ? 0 : 1;
    }
    EXPECT_EQ(moved, 0u) << "learn" << frame;
  }
}

// The stacked-box frames learn17-24 without their grid: segmented as an unorganized cloud (no depth
// edges, no creases, no viewpoint) 6 of their 20 boxes were named right and 7 merged into their
// neighbours (`cloudshape-bench --scenes ... --unorganized`); now as read: 18 here, where a box's
// report is the one holding most of its points (two boxes keep an `unknown` part, as read too).
TEST(MosdWithoutGrid, StackedBoxesAreBoxes) {
  if (mosd::data_missing()) GTEST_SKIP() << mosd::kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  int boxes = 0, objects = 0;
  for (int frame = 17; frame <= 24; ++frame) {
    const io::CloudFile file = io::read_cloud(mosd::frame_path(frame));
    const auto result =
        pipeline::recognize_cloud(file.points, GridLayout{}, cfg, "learn" + std::to_string(frame));
    for (const auto& [object, shape] : mosd::shapes_of_objects(file, result)) {
      ++objects;
      boxes += shape == "box" ? 1 : 0;
    }
  }
  EXPECT_EQ(objects, 20);
  EXPECT_GE(boxes, 17) << "of " << objects;
}

}  // namespace
}  // namespace cloudshape
