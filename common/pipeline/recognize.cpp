#include "pipeline/recognize.hpp"

#include <chrono>

#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/object_clouds.hpp"
#include "pipeline/solve.hpp"

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
  return recognize_cloud(points, GridLayout{}, cfg, source);
}

RecognitionResult recognize_cloud(const PointList& points, const GridLayout& grid,
                                  const config::PipelineConfig& cfg, const std::string& source) {
  RecognitionResult result;
  result.source = source;
  result.points_in = points.size();
  StageClock clock;

  const ObjectClouds clouds = object_clouds(points, grid, cfg.preprocess, cfg.segment);
  result.points_used = clouds.scene.points.size();
  result.resolution = clouds.scene.resolution;
  result.timings.preprocess_ms = clock.lap_ms();

  for (const ObjectCloud& o : clouds.objects) {
    const PlaneSegmentation planes = segment_planes(o.points, o.resolution, cfg.planes);
    result.timings.planes_ms += clock.lap_ms();
    const KeypointSet keypoints = find_keypoints(o.points, planes, o.resolution, cfg.keypoints);
    result.timings.keypoints_ms += clock.lap_ms();
    const Classification cls = classify_cloud(o.points, planes, keypoints, o.resolution, cfg.classify);
    result.timings.classify_ms += clock.lap_ms();
    result.objects.push_back(solve_object(o.points, planes, keypoints, cls, o.resolution, cfg.solve));
    result.objects.back().point_indices = o.raw_indices;
    result.timings.solve_ms += clock.lap_ms();
  }
  const StageTimings& t = result.timings;
  result.timings.total_ms = t.preprocess_ms + t.planes_ms + t.keypoints_ms + t.classify_ms + t.solve_ms;
  return result;
}

}  // namespace cloudshape::pipeline
