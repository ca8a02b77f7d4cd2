// Real Kinect frames under 3 mm of white noise per coordinate (twice the sensor's own at 1 m, as
// a noisier sensor or a farther view gives): the table is still found and removed, not reported.
#include <gtest/gtest.h>

#include <string>

#include "config/pipeline_config.hpp"
#include "io/cloud_reader.hpp"
#include "mosd_frames.hpp"
#include "pipeline/recognize.hpp"

namespace cloudshape {
namespace {

// Reports most of whose points are the table's (labels 1-9).
int table_reports(const io::CloudFile& file, const pipeline::RecognitionResult& result) {
  int reports = 0;
  for (const auto& o : result.objects) {
    std::size_t table = 0;
    for (std::uint32_t i : o.point_indices)
      table += file.labels[i] >= 1 && file.labels[i] <= 9 ? 1 : 0;
    reports += 2 * table > o.point_indices.size() ? 1 : 0;
  }
  return reports;
}

// One frame of each category, jittered by 2 point spacings (about 3 mm) as `cloudshape-bench
// --scenes --jitter 2.0` jitters them. The noise lifts table nodes above its band with tilted
// normals; counted as standing on it they spread what stands there over the table itself
// (learn1: 777 footprint cells against 283 as read), it fails structure_reach and comes out as
// objects: 13 table reports on these frames before and none of their 13 objects named right; 405
// table reports on all 45 frames' 135 runs.
TEST(MosdNoisyTable, TheTableIsNoObjectUnderThreeMillimetresOfNoise) {
  if (mosd::data_missing()) GTEST_SKIP() << mosd::kDir << " not present";
  const auto cfg = config::load_pipeline_config(CLOUDSHAPE_PIPELINE_YAML);
  int objects = 0, right = 0;
  for (int frame : {1, 10, 21, 29, 38}) {
    const io::CloudFile file = io::read_cloud(mosd::frame_path(frame));
    const auto result = pipeline::recognize_cloud(
        mosd::jittered(file.points, 2.0, 1000003ull * static_cast<std::uint64_t>(frame)), file.grid,
        cfg, "learn" + std::to_string(frame));
    EXPECT_EQ(table_reports(file, result), 0) << "learn" << frame;
    for (const auto& [object, shape] : mosd::shapes_of_objects(file, result)) {
      ++objects;
      right += (shape == "box" && frame <= 32) || (shape == "cylinder" && frame >= 25) ? 1 : 0;
    }
  }
  EXPECT_EQ(objects, 13);
  EXPECT_GE(right, 5) << "of " << objects;  // measured 6 (0 before: the table swallowed them)
}

}  // namespace
}  // namespace cloudshape
