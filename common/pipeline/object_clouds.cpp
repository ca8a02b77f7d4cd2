#include "pipeline/object_clouds.hpp"

#include <algorithm>
#include <numeric>

#include "pipeline/free_space.hpp"
#include "pipeline/surface_noise.hpp"
#include "segment/segment_scene.hpp"

namespace cloudshape::pipeline {
namespace {

// Points in a neighbourhood whose spread off its plane reads the noise.
constexpr std::size_t kNoiseNeighbours = 16;

}  // namespace

ObjectClouds object_clouds(const PointList& raw, const GridLayout& grid, const config::PreprocessConfig& pre,
                           const config::SegmentConfig& seg, parallel::ThreadPool* pool) {
  ObjectClouds out;
  segment::SceneSegmentation scene = segment::segment_scene(raw, grid, seg, pool);
  out.viewpoint = scene.viewpoint;
  // Nothing segmented is one object of every point (a thin sliver, a cloud too small for the
  // graph), unless structure was taken out: then the cloud is structure alone, and all of it as
  // one object would be a wall-sized wrong solid.
  if (scene.objects.empty() && scene.structure.empty() && !raw.empty()) {
    scene.objects.emplace_back(raw.size());
    std::iota(scene.objects.back().begin(), scene.objects.back().end(), 0u);
    scene.scan_lines.assign(1, 0);
  }
  // Where each pixel's depth is noisy on its own, more than the spacing of an object's points, a
  // band of a few resolutions about a surface is narrower than the noise and selects points that
  // happen to lie flat (a noisy ball's cap passes for a lid): the resolution is no finer than
  // pre.noise_resolution times the points' noise off their surface.
  const bool follow_noise = scene.noisy_pixels && pre.noise_resolution > 0.0;
  // Each object preprocessed in its own slot; the slots joined in object order.
  std::vector<PreprocessedCloud> done(scene.objects.size());
  parallel::for_blocks(pool, scene.objects.size(), 1, [&](std::size_t begin, std::size_t) {
    const std::vector<std::uint32_t>& members = scene.objects[begin];
    // An object of every point in input order (a lone solid) is the cloud itself: not copied.
    bool whole = members.size() == raw.size();
    for (std::size_t j = 0; whole && j < members.size(); ++j) whole = members[j] == j;
    PreprocessedCloud& p = done[begin];
    if (whole) {
      p = preprocess_cloud(raw, pre, pool);
    } else {
      PointList points;
      points.reserve(members.size());
      for (std::uint32_t i : members) points.push_back(raw[i]);
      p = preprocess_cloud(points, pre, pool);
    }
    if (follow_noise && p.tree)
      p.resolution = std::max(
          p.resolution, pre.noise_resolution * surface_noise(p.points, *p.tree, kNoiseNeighbours));
  });
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    PreprocessedCloud& p = done[k];
    if (p.points.empty()) continue;
    if (out.objects.empty()) {
      out.scene.resolution = p.resolution;
      out.scene.voxel_size = p.voxel_size;
    }
    out.scene.outliers_removed += p.outliers_removed;
    out.scene.points.insert(out.scene.points.end(), p.points.begin(), p.points.end());
    PointList about;
    if (scene.scan_lines[k] > 0 && scene.viewpoint && pre.free_space_reach > 0.0)
      about = returns_about(raw, p.points, *scene.viewpoint, pre.free_space_reach);
    out.objects.push_back({std::move(p.points), p.resolution, std::move(scene.objects[k]),
                           std::move(p.tree), scene.scan_lines[k], std::move(about)});
  }
  return out;
}

}  // namespace cloudshape::pipeline
