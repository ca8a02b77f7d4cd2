#include "pipeline/object_clouds.hpp"

#include <numeric>

#include "segment/segment_scene.hpp"

namespace cloudshape::pipeline {

ObjectClouds object_clouds(const PointList& raw, const GridLayout& grid, const config::PreprocessConfig& pre,
                           const config::SegmentConfig& seg) {
  ObjectClouds out;
  segment::SceneSegmentation scene = segment::segment_scene(raw, grid, seg);
  if (scene.objects.empty() && !raw.empty()) {
    scene.objects.emplace_back(raw.size());
    std::iota(scene.objects.back().begin(), scene.objects.back().end(), 0u);
  }
  for (std::vector<std::uint32_t>& indices : scene.objects) {
    PointList points;
    points.reserve(indices.size());
    for (std::uint32_t i : indices) points.push_back(raw[i]);
    PreprocessedCloud p = preprocess_cloud(points, pre);
    if (p.points.empty()) continue;
    if (out.objects.empty()) {
      out.scene.resolution = p.resolution;
      out.scene.voxel_size = p.voxel_size;
    }
    out.scene.outliers_removed += p.outliers_removed;
    out.scene.points.insert(out.scene.points.end(), p.points.begin(), p.points.end());
    out.objects.push_back({std::move(p.points), p.resolution, std::move(indices)});
  }
  return out;
}

}  // namespace cloudshape::pipeline
