// cloudshape-bench --scenes DIR: recognises every labelled scene in DIR and scores it against
// its per-point labels (scene_score.hpp) and expected shapes (scene_truth.hpp).
#pragma once

#include <string>

#include "config/pipeline_config.hpp"
#include "parallel/thread_pool.hpp"

namespace cloudshape::bench {

struct SceneOptions {
  std::string dir;
  // --truth FILE; empty: `default_truth` for the scenes it lists. A scene's sidecar
  // (<scene>.truth.json) overrides either.
  std::string truth;
  std::string default_truth;
  bool json = false;
  bool per_scene = false;    // one line per scene on stderr
  std::string config_label;  // what --json reports as the configuration used
  parallel::ThreadPool* pool = nullptr;  // --threads: recognize_cloud's threads (same answers)
  // --jitter: each scene is scored `jitter_runs` times, every coordinate moved by Gaussian noise
  // of this share of the scene's point spacing (seeded per scene and run), instead of once as
  // read. Far below a sensor's own noise, such a move changes nothing a scene shows: answers that
  // change with it sit on a decision's edge, and an unseen frame of the same kind lands either
  // side.
  double jitter = 0.0;
  int jitter_runs = 3;
  // --unorganized: each scene's pixel grid dropped before it is recognised, as an export of the
  // same frame to PLY or XYZ drops it (the same points, in the same order).
  bool unorganized = false;
  // --voxel SIZE: each scene downsampled to the centroids of voxels of SIZE (its units), each
  // labelled as most of its points, as a robot's pipeline often thins a frame before passing it
  // on (an unorganized cloud); 0: as read.
  double voxel = 0.0;
  // --decimate N: of an organized scene, every N-th pixel of every N-th row kept, on a grid N
  // times smaller each way: the frame a camera run at a lower resolution gives (2: 320 x 240 from
  // 640 x 480), as robots often run one for speed; 1: as read.
  int decimate = 1;
};

// Prints the table (or JSON) on stdout, progress on stderr when it is a terminal. Returns 0,
// or 2 after a one-line message naming the input for a bad directory, scene or truth file.
int run_scenes(const SceneOptions& options, const config::PipelineConfig& cfg);

}  // namespace cloudshape::bench
