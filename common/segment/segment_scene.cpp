#include "segment/segment_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/pca.hpp"
#include "geometry/voxel_grid.hpp"
#include "segment/cavity_join.hpp"
#include "segment/convex_segments.hpp"
#include "segment/neighbour_graph.hpp"
#include "segment/own_resolution.hpp"
#include "segment/pinhole_grid.hpp"
#include "segment/remainder_graph.hpp"
#include "segment/scan_beams.hpp"
#include "segment/scan_origin.hpp"
#include "segment/structure_contact.hpp"

namespace cloudshape::segment {
namespace {

// Points a block of the objects' assignment takes on the pool: each block keeps a list per
// object, joined after, which only pays for itself over many points.
constexpr std::size_t kPointsPerParallelBlock = 65536;

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

// The share of an object's points within cfg.structure_band of its own point spacings of one
// structure plane (the most): a lidar frame's strip of ground ring or wall the plane's band missed
// holds most of its points there; a solid standing on the plane has its own surface above it.
double in_structure_share(const PointList& points, const std::vector<std::uint32_t>& object,
                          const std::vector<StructurePlane>& structure, const config::SegmentConfig& cfg) {
  if (structure.empty() || object.empty()) return 0.0;
  PointList own;
  own.reserve(object.size());
  for (std::uint32_t i : object) own.push_back(points[i]);
  const double band = cfg.structure_band * geometry::mean_nearest_neighbour_distance(own);
  std::size_t most = 0;
  for (const StructurePlane& s : structure) {
    std::size_t within = 0;
    for (const Point& p : own) within += std::abs(s.plane.signed_distance(p)) <= band ? 1 : 0;
    most = std::max(most, within);
  }
  return static_cast<double>(most) / static_cast<double>(own.size());
}

// Per segment, whether it is a sliver a sensor leaves along silhouettes: narrow (narrow_groups),
// and in a depth image also a strip (cfg.fragment_min_elongation times as long as it is wide) or
// bordering another segment. A narrow segment there that is compact and alone is a small solid
// seen from afar: noisy pixels' depth noise swells their nodes' spacing, and a ball of a few
// hundred nodes is then as few spacings across as a strip. (A lidar frame's compact piece alone
// is mostly clutter: a pole's or a bush's few rings.)
std::vector<char> slivers(const NeighbourGraph& g, const std::vector<std::int32_t>& label,
                          const std::vector<std::vector<std::uint32_t>>& members, bool depth_image,
                          const config::SegmentConfig& cfg) {
  const auto segments = static_cast<std::int32_t>(members.size());
  std::vector<char> sliver = narrow_groups(g, label, segments, cfg.fragment_max_width);
  for (std::int32_t s = 0; s < segments && depth_image; ++s) {
    if (!sliver[s] || members[s].size() < 3) continue;
    const geometry::Pca pca = geometry::compute_pca(g.nodes, members[s]);
    const double across = std::sqrt(std::max(0.0, pca.eigenvalues(1)));
    if (std::sqrt(std::max(0.0, pca.eigenvalues(2))) >= cfg.fragment_min_elongation * across)
      continue;
    bool borders = false;
    for (std::uint32_t n : members[s]) {
      g.for_neighbours(
          n, [&](std::uint32_t m) { borders = borders || (label[m] >= 0 && label[m] != s); });
      if (borders) break;
    }
    sliver[s] = borders;
  }
  return sliver;
}

// `scan`: the viewpoint of the lidar frame this part of an unorganized cloud comes from, if any
// (a lidar frame in its sensor's frame, scan_origin, sees from the origin: normals towards it).
// An unorganized cloud without a lidar's viewpoint (`may_be_isolated`) is gridded to
// cfg.isolated_target_nodes first (a cloud too sparse for that to coarsen it: at the scene's
// budget, the graph the scene's path then reuses), and segmented there when that graph holds no
// plane reaching cfg.structure_reach times beyond what stands on it and the segmentation gives one
// object of all the points but a few (isolated_whole): a lone solid needs no finer graph. Otherwise
// (a support in view, several objects, a part left out) it is a scene, segmented again at
// cfg.voxel_target_nodes: what it would have been without the trial. `own_resolution`: the points
// are one lidar segment gridded alone (segment_graph).
SceneSegmentation segment_part(const PointList& points, const GridLayout& grid,
                               const config::SegmentConfig& cfg, parallel::ThreadPool* pool,
                               std::optional<std::optional<Point>> scan, bool may_be_isolated,
                               bool own_resolution = false);

// The objects in the points `indices` select, segmented again alone, when they would grid finer
// alone than at `spacing` (finer_on_its_own); none otherwise. Only a strict part of `points`: all
// of them would be this segmentation again.
std::optional<std::vector<std::vector<std::uint32_t>>> at_own_resolution(
    const PointList& points, const std::vector<std::uint32_t>& indices, double spacing,
    const config::SegmentConfig& cfg, parallel::ThreadPool* pool, const std::optional<Point>& scan) {
  if (indices.size() >= points.size()) return std::nullopt;
  PointList own;
  own.reserve(indices.size());
  for (std::uint32_t i : indices) own.push_back(points[i]);
  if (!finer_on_its_own(own, spacing, cfg, pool)) return std::nullopt;
  std::vector<std::vector<std::uint32_t>> parts =
      segment_part(own, GridLayout{}, cfg, pool, scan, false, true).objects;
  for (auto& part : parts) {
    for (std::uint32_t& i : part) i = indices[i];
  }
  return parts;
}

// Whether an unorganized cloud with a support in view is a depth camera's frame seen from the
// origin (the sensor's own frame, as drivers write it): every point on one side of the camera's
// plane z = 0, and the origin on the open side of the first structure plane, at least a quarter of
// the points' extent off it (a camera looks down at a table from well above it; a scene written in
// a world frame has its origin on its floor or table, or nowhere near a view of it).
bool seen_by_camera(const PointList& points, const std::vector<StructurePlane>& structure) {
  if (structure.empty() || !beyond_camera_plane(points)) return false;
  return structure.front().plane.signed_distance(Point::Zero()) >=
         0.25 * geometry::bounding_box(points).diagonal();
}

// Whether at least `share` of the nodes left in (not `removed`) face the origin, their normals
// turned out of their connected parts (orient_normals_outward): what a camera at the origin sees
// faces it, while an origin inside or behind the object sees the backs of its faces.
bool facing_the_origin(const NeighbourGraph& g, const std::vector<char>& removed, double share) {
  std::size_t left = 0, facing = 0;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (removed[n]) continue;
    ++left;
    if (g.normals[n].dot(g.nodes[n]) < 0.0) ++facing;
  }
  return static_cast<double>(facing) >= share * static_cast<double>(left);
}

// One object holding all the points but fewer than cfg.min_object_nodes of them: so few points
// make fewer nodes than an object needs at any resolution, so nothing the scene's finer graph
// could keep was left out.
bool isolated_whole(const SceneSegmentation& s, std::size_t points, const config::SegmentConfig& cfg) {
  return s.objects.size() == 1 &&
         static_cast<std::int64_t>(points - s.objects.front().size()) < cfg.min_object_nodes;
}

// The objects of `g`, a graph of `points` (`scan`: the lidar's viewpoint, if any). `isolated`: the
// trial's graph, on which the structure search found nothing to remove, and which already holds
// the cloud at its own resolution. `own_resolution`: `points` are one segment of a lidar frame
// gridded alone (at_own_resolution), as finely as their sampling allows, so that a node may hold a
// few points; a part there is an object when it holds cfg.min_object_nodes points, the count that
// sent the segment there.
SceneSegmentation segment_graph(NeighbourGraph g, bool isolated, const PointList& points,
                                const GridLayout& grid, const config::SegmentConfig& cfg,
                                parallel::ThreadPool* pool, const std::optional<Point>& scan,
                                bool own_resolution = false) {
  SceneSegmentation out;
  if (g.size() == 0) return out;
  out.graph_nodes = g.size();
  if (!grid.organized()) orient_to_viewpoint(g, scan);
  out.viewpoint = g.viewpoint;
  out.noisy_pixels = g.noisy_pixels;
  const bool from_inside = !grid.organized() && g.viewpoint.has_value();
  std::vector<char> removed(g.size(), 0);
  if (!isolated) out.structure = remove_structure(g, cfg, removed, pool, from_inside);
  // The cells at an object's foot hold points of the plane it stands on or against: an organized
  // cloud's objects leave those points behind. Not an unorganized cloud's: in a sparse lidar frame
  // a segment at a target's foot is often a strip of ground rings, which trimmed of its lowest
  // points rises like a solid of its own (there the finer graph leaves them out, below).
  const std::vector<StructureFootprint> footprints =
      grid.organized() ? structure_footprints(points, g, removed, out.structure, cfg) : std::vector<StructureFootprint>{};
  // What the structure leaves of a wide, sparse scene, at its own (finer) resolution; input
  // indices through `kept` from then on.
  std::vector<std::uint32_t> kept;
  if (!grid.organized() && !isolated) {
    if (std::optional<RemainderGraph> finer = finer_remainder_graph(points, g, removed, cfg, pool)) {
      // A coarse voxel where a solid meets its ground or wall holds points of both, and is kept
      // whole: the finer graph's nodes there within the plane's noise of the height its points
      // have around them are the plane's (a lidar's real ground is neither level nor flat over
      // tens of metres; a ball resting on it loses a cap a few centimetres high at its foot).
      const std::vector<StructureFootprint> coarse_structure =
          structure_footprints(points, g, removed, out.structure, cfg, true);
      g = std::move(finer->graph);
      kept = std::move(finer->points);
      removed.assign(g.size(), 0);
      for (std::uint32_t n = 0; n < g.size(); ++n) removed[n] = on_structure(coarse_structure, g.nodes[n]) ? 1 : 0;
      // Structure the coarse graph's connected parts missed (ground rings apart from the rest).
      const std::vector<StructurePlane> more = remove_structure(g, cfg, removed, pool, from_inside);
      out.structure.insert(out.structure.end(), more.begin(), more.end());
    }
  }
  // A depth camera's frame without its grid (downsampled, or never in raster order): every point
  // in front of the camera's plane, the support far on the camera's side, and what stands on it
  // facing the camera (cfg.camera_facing_share: a YCB brick seen from elsewhere, its origin inside
  // it, passed for a camera's view, and a face came apart from the rest). Its normals then face the
  // camera, as an organized frame's do, and the depth image's segmentation rules hold.
  const bool viewed = g.viewpoint.has_value();
  if (!viewed) orient_normals_outward(g, removed);
  const bool camera = !grid.organized() && !viewed && !isolated &&
                      seen_by_camera(points, out.structure) &&
                      facing_the_origin(g, removed, cfg.camera_facing_share);
  if (camera) {
    orient_to_viewpoint(g, Point::Zero());
    out.viewpoint = g.viewpoint;
    out.camera_view = true;
  }
  std::vector<std::int32_t> label = convex_segments(g, removed, cfg, grid.organized() || camera);
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
  const std::vector<char> narrow = slivers(g, label, members, grid.organized() || camera, cfg);
  std::vector<std::int32_t> object_of_segment(static_cast<std::size_t>(segments), -1);
  // Input points per segment, for a segment segmented again at its own resolution: in a lidar
  // frame, where a narrow segment may still hold a small target among ground rings (elsewhere a
  // narrow strip alone would pass for an object at its own scale).
  std::vector<std::vector<std::uint32_t>> segment_points(from_inside ? static_cast<std::size_t>(segments) : 0);
  for (std::uint32_t i = 0; i < g.node_of_point.size() && !segment_points.empty(); ++i) {
    const std::uint32_t n = g.node_of_point[i];
    if (n != kNoNode && label[n] >= 0) segment_points[label[n]].push_back(kept.empty() ? i : kept[i]);
  }
  std::int32_t objects = 0;
  std::vector<std::vector<std::uint32_t>> refined;
  for (std::int32_t s = 0; s < segments; ++s) {
    // In a lidar frame a segment too small at the scene's resolution is tried at its own first: a
    // ball among ground and walls may be a few dozen of the scene's coarse voxels and hundreds of
    // points. One with fewer points than cfg.min_object_nodes makes no object at any resolution.
    const bool few_nodes =
        own_resolution && !segment_points.empty()
            ? static_cast<std::int64_t>(segment_points[s].size()) < cfg.min_object_nodes
            : static_cast<double>(members[s].size()) < min_nodes;
    if (few_nodes && (segment_points.empty() ||
                      static_cast<std::int64_t>(segment_points[s].size()) < cfg.min_object_nodes)) {
      continue;
    }
    if (!segment_points.empty()) {
      std::vector<double> spacing;
      for (std::uint32_t n : members[s]) spacing.push_back(g.spacing[n]);
      std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
      if (auto parts = at_own_resolution(points, segment_points[s], spacing[spacing.size() / 2], cfg, pool, scan)) {
        for (auto& part : *parts) refined.push_back(std::move(part));
        continue;
      }
    }
    if (few_nodes) continue;
    if (narrow[s] && static_cast<double>(members[s].size()) < cfg.fragment_max_share * static_cast<double>(largest)) {
      continue;
    }
    if (leftover_of_structure(g, members[s], out.structure, cfg)) continue;
    object_of_segment[s] = objects++;
  }
  // A large cloud's points in blocks on the pool, each block with its own lists, joined in block
  // order: the lists one pass in point order makes.
  const std::size_t count = g.node_of_point.size();
  const std::size_t per_block =
      pool != nullptr && pool->size() > 1 && count >= kPointsPerParallelBlock
          ? kPointsPerParallelBlock
          : std::max<std::size_t>(1, count);
  const std::size_t blocks = (count + per_block - 1) / per_block;
  std::vector<std::vector<std::vector<std::uint32_t>>> of_block(blocks);
  parallel::for_blocks(pool, count, per_block, [&](std::size_t begin, std::size_t end) {
    std::vector<std::vector<std::uint32_t>>& lists = of_block[begin / per_block];
    lists.resize(static_cast<std::size_t>(objects));
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint32_t n = g.node_of_point[i];
      if (n == kNoNode || label[n] < 0) continue;
      const std::int32_t o = object_of_segment[label[n]];
      const std::uint32_t p = kept.empty() ? static_cast<std::uint32_t>(i) : kept[i];
      if (o >= 0 && (footprints.empty() || !on_structure(footprints, points[p])))
        lists[o].push_back(p);
    }
  });
  if (of_block.size() == 1) {
    out.objects = std::move(of_block.front());
  } else {
    out.objects.resize(static_cast<std::size_t>(objects));
    for (std::size_t o = 0; o < out.objects.size(); ++o) {
      std::size_t total = 0;
      for (const auto& lists : of_block) total += lists[o].size();
      out.objects[o].reserve(total);
      for (const auto& lists : of_block)
        out.objects[o].insert(out.objects[o].end(), lists[o].begin(), lists[o].end());
    }
  }
  for (auto& part : refined) out.objects.push_back(std::move(part));
  out.objects.erase(std::remove_if(out.objects.begin(), out.objects.end(), [](const auto& o) { return o.empty(); }),
                    out.objects.end());
  std::stable_sort(out.objects.begin(), out.objects.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return out;
}

SceneSegmentation segment_part(const PointList& points, const GridLayout& grid,
                               const config::SegmentConfig& cfg, parallel::ThreadPool* pool,
                               std::optional<std::optional<Point>> scan, bool may_be_isolated,
                               bool own_resolution) {
  if (!grid.organized() && !scan) scan = scan_origin(points, cfg, pool);
  const std::optional<Point> view = scan ? *scan : std::nullopt;
  if (grid.organized() && grid.pixel.size() == points.size()) {
    return segment_graph(build_organized_graph(points, grid, cfg, pool), false, points, grid, cfg, pool, view);
  }
  may_be_isolated = may_be_isolated && !grid.organized() && !view && cfg.isolated_target_nodes > 0;
  // One bounding box for the budgets and either graph: one pass over the points, not three.
  const geometry::Bounds box = geometry::bounding_box(points, 1, pool);
  const auto [scene, coarse] =
      budget_voxels(points, cfg, may_be_isolated ? cfg.isolated_target_nodes : 0, pool, &box);
  // A cloud too sparse for the isolated budget to coarsen it (a 10 000-point solid) is tried on the
  // scene's own graph, which the scene's path then reuses: a lone solid skips the scene path's
  // structure removal and finer remainder graph there too.
  std::optional<NeighbourGraph> scene_graph;
  if (may_be_isolated) {
    NeighbourGraph trial = build_voxel_graph(points, coarse, cfg.target_nodes, cfg, pool, &box);
    std::vector<char> none(trial.size(), 0);
    bool reaches = false;
    remove_structure(trial, cfg, none, pool, false, &reaches);
    const bool scenes_own = !(coarse > scene);
    if (!reaches) {
      // Kept for the scene's path in case the trial's objects are not one whole solid.
      if (scenes_own) scene_graph = trial;
      SceneSegmentation out = segment_graph(std::move(trial), true, points, grid, cfg, pool, view);
      out.lone_solid = true;
      if (isolated_whole(out, points.size(), cfg)) return out;
    } else if (scenes_own) {
      scene_graph = std::move(trial);
    }
  }
  if (!scene_graph)
    scene_graph = build_voxel_graph(points, scene, cfg.target_nodes, cfg, pool, &box);
  return segment_graph(std::move(*scene_graph), false, points, grid, cfg, pool, view,
                       own_resolution);
}

}  // namespace

SceneSegmentation segment_scene(const PointList& points, const GridLayout& grid, const config::SegmentConfig& cfg,
                                parallel::ThreadPool* pool) {
  // A depth image that lost its grid on the way (an export to PLY or XYZ) is still one.
  if (!grid.organized()) {
    if (const std::optional<GridLayout> pixels = pinhole_grid(points))
      return segment_scene(points, *pixels, cfg, pool);
  }
  SceneSegmentation out = segment_part(points, grid, cfg, pool, std::nullopt, true);
  // A lidar frame's object on fewer than cfg.scan_object_min_beams beams is a strip of its ground
  // or walls (one ring samples no vertical extent), and one mostly in a structure plane's band is
  // a leftover of that plane.
  if (grid.organized() || !out.viewpoint || out.camera_view) {
    out.scan_lines.assign(out.objects.size(), 0);
    return out;
  }
  const std::vector<std::int32_t> beam_of = scan_beam_of_points(points, cfg);
  const auto min_beams = static_cast<std::size_t>(cfg.scan_object_min_beams);
  std::vector<std::vector<std::uint32_t>> kept;
  for (auto& o : out.objects) {
    const std::size_t beams = beams_spanned(beam_of, o);
    if (beams < min_beams || in_structure_share(points, o, out.structure, cfg) >= cfg.scan_leftover_share) continue;
    kept.push_back(std::move(o));
    out.scan_lines.push_back(static_cast<std::uint32_t>(beams));
  }
  out.objects = std::move(kept);
  return out;
}

}  // namespace cloudshape::segment
