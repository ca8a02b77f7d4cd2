#include "pipeline/recognize.hpp"

#include <chrono>
#include <optional>

#include "geometry/kdtree.hpp"
#include "pipeline/classify.hpp"
#include "pipeline/keypoints.hpp"
#include "pipeline/object_clouds.hpp"
#include "pipeline/planes.hpp"
#include "pipeline/solve.hpp"
#include "pipeline/view_noise.hpp"

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
                                  const std::string& source, parallel::ThreadPool* pool) {
  return recognize_cloud(points, GridLayout{}, cfg, source, pool);
}

RecognitionResult recognize_cloud(const PointList& points, const GridLayout& grid,
                                  const config::PipelineConfig& cfg, const std::string& source,
                                  parallel::ThreadPool* pool) {
  RecognitionResult result;
  result.source = source;
  result.points_in = points.size();
  StageClock wall;
  StageClock clock;

  const ObjectClouds clouds = object_clouds(points, grid, cfg.preprocess, cfg.segment, pool);
  result.points_used = clouds.scene.points.size();
  result.resolution = clouds.scene.resolution;
  result.timings.preprocess_ms = clock.lap_ms();

  // Objects are independent and every stage seeds its own RANSAC: each runs alone, its result
  // in its own slot, and the slots are read in object order. A stage's time is summed over the
  // objects (with several threads more than the wall clock it took).
  std::vector<ObjectResult> objects(clouds.objects.size());
  std::vector<StageTimings> times(clouds.objects.size());
  parallel::for_blocks(pool, clouds.objects.size(), 1, [&](std::size_t begin, std::size_t) {
    const ObjectCloud& o = clouds.objects[begin];
    StageTimings& t = times[begin];
    StageClock object_clock;
    // One search tree over the object's points for every stage that needs neighbours: the one
    // preprocessing built for the resolution.
    std::optional<geometry::KdTree> own_tree;
    const geometry::KdTree& tree = o.tree ? *o.tree : own_tree.emplace(o.points);
    // The pool splits an object's own work only while it is not busy with the objects: one
    // object has both threads, several run side by side.
    const PlaneSegmentation planes =
        segment_planes(o.points, o.resolution, cfg.planes, &tree, pool,
                       noise_viewpoint(clouds.viewpoint, o.scan_lines));
    t.planes_ms = object_clock.lap_ms();
    const KeypointSet keypoints = find_keypoints(o.points, planes, o.resolution, cfg.keypoints, &tree);
    t.keypoints_ms = object_clock.lap_ms();
    const Classification cls = classify_cloud(o.points, planes, keypoints, o.resolution, cfg.classify);
    t.classify_ms = object_clock.lap_ms();
    objects[begin] =
        solve_object(o.points, planes, keypoints, cls, o.resolution, cfg.solve, &tree,
                     clouds.viewpoint, clouds.objects.size(), o.scan_lines, pool, &o.returns_about);
    objects[begin].point_indices = o.raw_indices;
    t.solve_ms = object_clock.lap_ms();
  });
  for (std::size_t i = 0; i < objects.size(); ++i) {
    result.objects.push_back(std::move(objects[i]));
    result.timings.planes_ms += times[i].planes_ms;
    result.timings.keypoints_ms += times[i].keypoints_ms;
    result.timings.classify_ms += times[i].classify_ms;
    result.timings.solve_ms += times[i].solve_ms;
  }
  // The wall clock around the whole call: with one thread the stages' sum, with more less.
  result.timings.total_ms = wall.lap_ms();
  return result;
}

}  // namespace cloudshape::pipeline
