// Small objects in large scenes: the scene's structural planes (ground, walls) are cut away,
// the small components left over are the objects, each gridded again from its own raw points.
#pragma once

#include <optional>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "pipeline/preprocess.hpp"

namespace cloudshape::pipeline {

// One object's points and the resolution (mean nearest-neighbour distance) they were
// gridded at: the scene's, or the object's own for an object found among structure.
struct ObjectCloud {
  PointList points;
  double resolution = 0.0;
};

// `pre` is `raw` preprocessed with `cfg`. Cuts away the structural planes of the scene: one
// after the other, the plane through most points whose own (k-NN) normals agree with it, while
// it spans cfg.structure_min_extent of the scene diagonal and holds cfg.structure_min_share of
// the points (at most cfg.structure_max_planes); together they must hold
// cfg.structure_min_total. The components left over (cells of cfg.object_gap resolutions)
// that span at most cfg.scene_object_max_extent of the diagonal and lie over a structural
// plane reaching beyond them by cfg.scene_object_margin times their extent on three of four
// sides are objects. Each object's raw points (those in or next to its cells, off every
// structural plane) are preprocessed again without the isolated-voxel filter (they passed it
// at the scene's scale; at the object's own, scan rings would look isolated); an object with
// fewer than cfg.scene_object_min_points raw points, or flat (thinner than
// cfg.fragment_max_width of its own resolutions), is dropped. nullopt when the cloud is no
// such scene.
std::optional<std::vector<ObjectCloud>> scene_objects(const PointList& raw, const PreprocessedCloud& pre,
                                                      const config::PreprocessConfig& cfg);

}  // namespace cloudshape::pipeline
