#include "segment/segment_scene.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/pca.hpp"
#include "segment/cavity_join.hpp"
#include "segment/convex_segments.hpp"
#include "segment/neighbour_graph.hpp"

namespace cloudshape::segment {
namespace {

// A flat segment (thinner than its node spacing) within two bands of a structure plane and
// parallel to it is a piece of it the plane's own band missed (a table's far edge), not an object.
bool leftover_of_structure(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes,
                           const std::vector<StructurePlane>& structure, const config::SegmentConfig& cfg) {
  if (structure.empty() || nodes.size() < 3) return false;
  const geometry::Pca pca = geometry::compute_pca(g.nodes, nodes);
  double spacing = 0.0;
  for (std::uint32_t n : nodes) spacing += g.spacing[n];
  spacing /= static_cast<double>(nodes.size());
  const double thickness = std::sqrt(std::max(0.0, pca.eigenvalues(0)));
  if (thickness > spacing) return false;
  const Eigen::Vector3d normal = pca.eigenvectors.col(0);
  for (const StructurePlane& s : structure) {
    if (std::abs(normal.dot(s.plane.normal)) >= 0.9 &&
        std::abs(s.plane.signed_distance(pca.centroid)) <= 2.0 * cfg.structure_band * spacing) {
      return true;
    }
  }
  return false;
}

}  // namespace

SceneSegmentation segment_scene(const PointList& points, const GridLayout& grid, const config::SegmentConfig& cfg,
                                parallel::ThreadPool* pool) {
  SceneSegmentation out;
  NeighbourGraph g = grid.organized() && grid.pixel.size() == points.size()
                         ? build_organized_graph(points, grid, cfg, pool)
                         : build_voxel_graph(points, cfg, pool);
  out.viewpoint = g.viewpoint;
  if (g.size() == 0) return out;
  std::vector<char> removed(g.size(), 0);
  out.structure = remove_structure(g, cfg, removed, pool);
  if (!g.viewpoint) orient_normals_outward(g, removed);
  std::vector<std::int32_t> label = convex_segments(g, removed, cfg);
  join_cavities(g, label, cfg);

  std::int32_t segments = 0;
  for (std::int32_t l : label) segments = std::max(segments, l + 1);
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(segments));
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (label[n] >= 0) members[label[n]].push_back(n);
  }
  const double min_nodes = std::max(static_cast<double>(cfg.min_object_nodes),
                                    cfg.min_object_share * static_cast<double>(g.size()));
  std::size_t largest = 0;
  for (const auto& m : members) largest = std::max(largest, m.size());
  const std::vector<char> narrow = narrow_groups(g, label, segments, cfg.fragment_max_width);
  std::vector<std::int32_t> object_of_segment(static_cast<std::size_t>(segments), -1);
  std::int32_t objects = 0;
  for (std::int32_t s = 0; s < segments; ++s) {
    if (static_cast<double>(members[s].size()) < min_nodes) continue;
    if (narrow[s] && static_cast<double>(members[s].size()) < cfg.fragment_max_share * static_cast<double>(largest)) {
      continue;
    }
    if (leftover_of_structure(g, members[s], out.structure, cfg)) continue;
    object_of_segment[s] = objects++;
  }
  out.objects.resize(static_cast<std::size_t>(objects));
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const std::uint32_t n = g.node_of_point[i];
    if (n == kNoNode || label[n] < 0) continue;
    const std::int32_t o = object_of_segment[label[n]];
    if (o >= 0) out.objects[o].push_back(i);
  }
  std::stable_sort(out.objects.begin(), out.objects.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return out;
}

}  // namespace cloudshape::segment
