#include "pipeline/object_clouds.hpp"

#include "pipeline/split_objects.hpp"

namespace cloudshape::pipeline {

ObjectClouds object_clouds(const PointList& raw, const config::PreprocessConfig& cfg) {
  return object_clouds(raw, GridLayout{}, cfg);
}

ObjectClouds object_clouds(const PointList& raw, const GridLayout& /*grid*/, const config::PreprocessConfig& cfg) {
  ObjectClouds out;
  out.scene = preprocess_cloud(raw, cfg);
  bool support_removed = false;
  std::vector<PointList> parts = split_objects(out.scene.points, out.scene.resolution, cfg, nullptr, &support_removed);
  if (cfg.split_objects && !support_removed) {
    if (auto objects = scene_objects(raw, out.scene, cfg)) {
      out.objects = std::move(*objects);
      return out;
    }
  }
  for (PointList& part : parts) out.objects.push_back({std::move(part), out.scene.resolution});
  return out;
}

}  // namespace cloudshape::pipeline
