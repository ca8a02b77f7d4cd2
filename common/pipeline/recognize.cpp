#include "pipeline/recognize.hpp"

#include <chrono>

#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/preprocess.hpp"
#include "pipeline/solve.hpp"
#include "pipeline/split_objects.hpp"

namespace cloudshape::pipeline {
namespace {

class StageClock {
 public:
  double lap_ms() {
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

RecognitionResult recognize_cloud(const PointList& points, const config::PipelineConfig& cfg,
                                  const std::string& source) {
  RecognitionResult result;
  result.source = source;
  result.points_in = points.size();
  StageClock clock;

  const PreprocessedCloud pre = preprocess_cloud(points, cfg.preprocess);
  result.points_used = pre.points.size();
  result.resolution = pre.resolution;
  result.timings.preprocess_ms = clock.lap_ms();

  const std::vector<PointList> objects = split_objects(pre.points, pre.resolution, cfg.preprocess);
  result.timings.preprocess_ms += clock.lap_ms();

  for (const PointList& object : objects) {
    const PlaneSegmentation planes = segment_planes(object, pre.resolution, cfg.planes);
    result.timings.planes_ms += clock.lap_ms();
    const KeypointSet keypoints = find_keypoints(object, planes, pre.resolution, cfg.keypoints);
    result.timings.keypoints_ms += clock.lap_ms();
    const Classification cls = classify_cloud(object, planes, keypoints, pre.resolution, cfg.classify);
    result.timings.classify_ms += clock.lap_ms();
    result.objects.push_back(solve_object(object, planes, keypoints, cls, pre.resolution, cfg.solve));
    result.timings.solve_ms += clock.lap_ms();
  }
  const StageTimings& t = result.timings;
  result.timings.total_ms = t.preprocess_ms + t.planes_ms + t.keypoints_ms + t.classify_ms + t.solve_ms;
  return result;
}

}  // namespace cloudshape::pipeline
