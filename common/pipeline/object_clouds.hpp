// From a raw cloud to its objects: preprocessing, then either the support-plane split of
// table-top scenes and lone objects or, among a scene's structure, its small objects.
#pragma once

#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"
#include "pipeline/preprocess.hpp"
#include "pipeline/scene_objects.hpp"

namespace cloudshape::pipeline {

struct ObjectClouds {
  PreprocessedCloud scene;           // the whole cloud, preprocessed
  std::vector<ObjectCloud> objects;  // one cloud per object, largest first
};

// preprocess_cloud, then split_objects; when no support plane was cut away and the cloud
// is a scene of structural planes with small objects among them (scene_objects), those
// objects instead, each at its own resolution.
ObjectClouds object_clouds(const PointList& raw, const config::PreprocessConfig& cfg);

// The same for a cloud with its sensor layout (organized when grid.organized()).
ObjectClouds object_clouds(const PointList& raw, const GridLayout& grid, const config::PreprocessConfig& cfg);

}  // namespace cloudshape::pipeline
