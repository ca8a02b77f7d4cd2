// Real Kinect boxes moved by a twentieth of their point spacing (0.1 mm, far below the sensor's
// noise) stay boxes: a prism outline placed on a cap's ragged border does not outbid the box's
// faces.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "config/pipeline_config.hpp"
#include "geometry/voxel_grid.hpp"
#include "io/cloud_reader.hpp"
#include "mosd_frames.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape {
namespace {

// learn3, learn15 and learn18 (boxes apart, three boxes in a row, stacked boxes), each under four
// seeded jitters of 0.05 of its point spacing (cloudshape-bench --scenes --jitter does the same):
// without solve.guessed_side_cost (0) learn3's box under seed 4 is a prism whose sides but one were
// traced on its top's border, explaining a few per cent more points than the box's faces; with the
// bench's own jitter seeds 3 of 135 runs of the 45 frames named a box so. None may now.
TEST(MosdJitteredBoxes, NoBoxIsAPrism) {
  if (mosd::data_missing()) GTEST_SKIP() << mosd::kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  for (int frame : {3, 15, 18}) {
    const io::CloudFile file = io::read_cloud(mosd::frame_path(frame));
    const double sigma = 0.05 * geometry::mean_nearest_neighbour_distance(file.points);
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      PointList points = file.points;
      std::mt19937_64 rng(seed);
      std::normal_distribution<double> noise(0.0, sigma);
      for (Point& p : points) p += Point(noise(rng), noise(rng), noise(rng));
      const auto result =
          pipeline::recognize_cloud(points, file.grid, cfg, "learn" + std::to_string(frame));
      for (const auto& o : result.objects)
        EXPECT_NE(o.shape, "prism") << "learn" << frame << ", seed " << seed;
    }
  }
}

}  // namespace
}  // namespace cloudshape
