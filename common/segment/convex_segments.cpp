#include "segment/convex_segments.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <unordered_map>

#include "geometry/pca.hpp"
#include "segment/concave_cuts.hpp"
#include "segment/crease_overlap.hpp"
#include "segment/planar_pieces.hpp"

namespace cloudshape::segment {
namespace {

constexpr double kPi = 3.14159265358979323846;

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

// Labels connected groups of active nodes, joining across the edges `joins` accepts.
template <class Joins>
std::vector<std::int32_t> flood(const NeighbourGraph& g, const std::vector<char>& removed, Joins&& joins,
                                std::int32_t& count) {
  std::vector<std::int32_t> label(g.size(), -1);
  std::vector<std::uint32_t> stack;
  count = 0;
  for (std::uint32_t seed = 0; seed < g.size(); ++seed) {
    if (removed[seed] || label[seed] >= 0) continue;
    label[seed] = count;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::uint32_t n = stack.back();
      stack.pop_back();
      g.for_neighbours(n, [&](std::uint32_t m) {
        if (!removed[m] && label[m] < 0 && joins(n, m)) {
          label[m] = count;
          stack.push_back(m);
        }
      });
    }
    ++count;
  }
  return label;
}

std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

}  // namespace

std::vector<char> narrow_groups(const NeighbourGraph& g, const std::vector<std::int32_t>& group, std::int32_t groups,
                                double max_width) {
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(groups));
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (group[n] >= 0) members[group[n]].push_back(n);
  }
  std::vector<char> narrow(static_cast<std::size_t>(groups), 0);
  for (std::int32_t k = 0; k < groups; ++k) {
    const auto& m = members[k];
    if (m.size() < 3) {
      narrow[k] = 1;
      continue;
    }
    double spacing = 0.0;
    for (std::uint32_t n : m) spacing += g.spacing[n];
    spacing /= static_cast<double>(m.size());
    const geometry::Pca pca = geometry::compute_pca(g.nodes, m);
    narrow[k] = std::sqrt(std::max(0.0, pca.eigenvalues(1))) < max_width * spacing;
  }
  return narrow;
}

void orient_normals_outward(NeighbourGraph& g, const std::vector<char>& removed) {
  std::int32_t count = 0;
  const std::vector<std::int32_t> comp = flood(g, removed, [](std::uint32_t, std::uint32_t) { return true; }, count);
  std::vector<Eigen::Vector3d> centroid(static_cast<std::size_t>(count), Eigen::Vector3d::Zero());
  std::vector<std::size_t> size(static_cast<std::size_t>(count), 0);
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (comp[n] < 0) continue;
    centroid[comp[n]] += g.nodes[n];
    ++size[comp[n]];
  }
  for (std::int32_t c = 0; c < count; ++c) centroid[c] /= static_cast<double>(size[c]);
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (comp[n] >= 0 && g.normals[n].dot(g.nodes[n] - centroid[comp[n]]) < 0.0) g.normals[n] = -g.normals[n];
  }
}

std::vector<std::int32_t> convex_segments(const NeighbourGraph& g, const std::vector<char>& removed,
                                          const config::SegmentConfig& cfg, bool depth_image) {
  const double smooth_cos = std::cos(cfg.smooth_degrees * kPi / 180.0);
  const double tolerance_cos = std::cos(cfg.convex_tolerance_degrees * kPi / 180.0);
  // Patches grow over surface nodes only: edge and corner nodes (curved beyond
  // cfg.edge_curvature) have normals blurred between two faces, which would let a patch creep
  // around an edge, and would judge a junction on a scale too small to see its shape.
  std::vector<char> edge_node(g.size(), 0);
  // A node on a concave crease (organized graphs mark them) lies on an edge as well.
  for (std::uint32_t n = 0; n < g.size(); ++n)
    edge_node[n] = !removed[n] && (g.curvature[n] >= cfg.edge_curvature || (!g.crease.empty() && g.crease[n]));
  // A component that is a line has no surface to judge: it stays whole.
  std::int32_t components = 0;
  const std::vector<std::int32_t> component =
      flood(g, removed, [](std::uint32_t, std::uint32_t) { return true; }, components);
  std::vector<char> line_like = narrow_groups(g, component, components, cfg.fragment_max_width);
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (component[n] >= 0 && line_like[component[n]]) edge_node[n] = 0;
  }
  std::vector<char> not_surface(g.size(), 0);
  for (std::uint32_t n = 0; n < g.size(); ++n) not_surface[n] = removed[n] || edge_node[n];
  std::int32_t patches = 0;
  std::vector<std::int32_t> patch = flood(
      g, not_surface,
      [&](std::uint32_t a, std::uint32_t b) {
        return line_like[component[a]] || g.normals[a].dot(g.normals[b]) >= smooth_cos;
      },
      patches);
  // In a depth image a patch of offset flat pieces (faces of two solids touching at a corner) is
  // split into them; nodes in no piece join the nearest as edge nodes do.
  if (depth_image && split_planar_pieces(g, patch, patches, cfg)) {
    for (std::uint32_t n = 0; n < g.size(); ++n) {
      if (!not_surface[n] && patch[n] < 0) edge_node[n] = 1;
    }
  }

  // Edge nodes join the nearest patch (breadth first), remembering the surface node they came
  // from: a junction is judged between the surface nodes on either side of the edge band.
  std::vector<std::uint32_t> origin(g.size(), kNoNode);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (patch[n] >= 0) {
      origin[n] = n;
      queue.push_back(n);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::uint32_t n = queue[head];
    g.for_neighbours(n, [&](std::uint32_t m) {
      if (edge_node[m] && patch[m] < 0) {
        patch[m] = patch[n];
        origin[m] = origin[n];
        queue.push_back(m);
      }
    });
  }

  // Every edge between two patches votes on their junction: convex or concave. Judged again
  // after a concave cut splits a patch (the junctions of its two pieces).
  struct Junction {
    std::uint32_t convex = 0;
    std::uint32_t total = 0;
    std::uint32_t edge = 0;  // convex and at an angle: an edge between two faces of one solid
  };
  const auto judge_junctions = [&](const std::vector<std::int32_t>& labels) {
    std::unordered_map<std::uint64_t, Junction> out;
    for (std::uint32_t a = 0; a < g.size(); ++a) {
      if (labels[a] < 0) continue;
      g.for_neighbours(a, [&](std::uint32_t b) {
        if (b <= a || labels[b] < 0 || labels[b] == labels[a]) return;
        Junction& j = out[pair_key(static_cast<std::uint32_t>(labels[a]), static_cast<std::uint32_t>(labels[b]))];
        ++j.total;
        const std::uint32_t oa = origin[a];
        const std::uint32_t ob = origin[b];
        const bool flat = g.normals[oa].dot(g.normals[ob]) >= tolerance_cos;
        const bool turns_out = (g.normals[oa] - g.normals[ob]).dot(g.nodes[oa] - g.nodes[ob]) >= 0.0;
        if (flat || turns_out) ++j.convex;
        if (!flat && turns_out) ++j.edge;
      });
    }
    return out;
  };
  const auto is_convex = [&](const Junction& j) {
    return static_cast<double>(j.convex) >= cfg.convex_share * static_cast<double>(j.total);
  };
  const auto is_edge = [&](const Junction& j) {
    return static_cast<double>(j.edge) >= cfg.convex_share * static_cast<double>(j.total);
  };
  // The junctions' keys in order: the same joins whatever the map's iteration order.
  const auto sorted_keys = [](const std::unordered_map<std::uint64_t, Junction>& judged) {
    std::vector<std::uint64_t> sorted;
    sorted.reserve(judged.size());
    for (const auto& entry : judged) sorted.push_back(entry.first);
    std::sort(sorted.begin(), sorted.end());
    return sorted;
  };
  // The concave junctions and the convex edges, in the order of their keys.
  const auto pairs_of = [&](const std::unordered_map<std::uint64_t, Junction>& judged) {
    JunctionPairs out;
    for (std::uint64_t key : sorted_keys(judged)) {
      const Junction& j = judged.at(key);
      const PatchJunction ab{static_cast<std::uint32_t>(key >> 32),
                             static_cast<std::uint32_t>(key & 0xffffffffu), j.total};
      if (!is_convex(j)) out.concave.push_back(ab);
      if (is_edge(j)) out.edges.push_back(ab);
    }
    return out;
  };
  std::unordered_map<std::uint64_t, Junction> junctions = judge_junctions(patch);
  UnionFind segments(static_cast<std::size_t>(patches));
  std::vector<std::size_t> patch_size(static_cast<std::size_t>(patches), 0);
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (patch[n] >= 0) ++patch_size[patch[n]];
  }
  // In a depth image patches of min_object_nodes or more join first; a junction they reject
  // (concave, or no shared crease) is remembered. A sliver (an edge's noise, a step's strip finer
  // than the graph) is too small to judge by: it joins across its convex junctions in a second
  // pass, but never two groups whose own junction was rejected, which it would bridge. Neither rule is applied
  // elsewhere, where both split solids (measured): without a viewpoint the normals are turned
  // outward from a centroid, which flips them across a non-convex solid's faces (a star or plus
  // prism's); a lidar's rings cut every face into strips whose spans say nothing of the face.
  std::optional<CreaseOverlap> crease;
  if (depth_image) {
    std::vector<char> surface(g.size(), 0);
    for (std::uint32_t n = 0; n < g.size(); ++n) surface[n] = patch[n] >= 0 && origin[n] == n;
    crease.emplace(g, patch, surface, patches, cfg.crease_band);
  }
  const std::vector<std::uint64_t> keys = sorted_keys(junctions);
  std::vector<std::vector<std::uint32_t>> rejected(static_cast<std::size_t>(patches));
  std::vector<std::uint64_t> sliver_joins;
  for (std::uint64_t key : keys) {
    const Junction& j = junctions.at(key);
    const auto a = static_cast<std::uint32_t>(key >> 32);
    const auto b = static_cast<std::uint32_t>(key & 0xffffffffu);
    const bool convex = is_convex(j);
    // Two patches side by side and parallel (two cans' lids at one height, touching) meet along a
    // few edges; one face parted by a seam of edge nodes meets itself along the seam's length.
    const bool parallel = !is_edge(j);
    const bool long_enough =
        !depth_image || !parallel ||
        static_cast<double>(j.total) >=
            cfg.flat_junction_length * std::sqrt(static_cast<double>(std::min(patch_size[a], patch_size[b])));
    const bool joins = convex && long_enough && (!crease || crease->shares_crease(a, b, tolerance_cos, cfg.crease_overlap));
    const bool slivers =
        depth_image && static_cast<std::int64_t>(std::min(patch_size[a], patch_size[b])) < cfg.min_object_nodes;
    if (slivers) {
      if (joins) sliver_joins.push_back(key);
    } else if (joins) {
      segments.join(a, b);
    } else {
      rejected[a].push_back(b);
      rejected[b].push_back(a);
    }
  }
  // Rejections per group root, so that a check sees every member's.
  std::vector<std::vector<std::uint32_t>> rejected_by_root(static_cast<std::size_t>(patches));
  for (std::uint32_t p = 0; p < static_cast<std::uint32_t>(patches); ++p) {
    auto& into = rejected_by_root[segments.find(p)];
    into.insert(into.end(), rejected[p].begin(), rejected[p].end());
  }
  for (std::uint64_t key : sliver_joins) {
    const std::uint32_t ra = segments.find(static_cast<std::uint32_t>(key >> 32));
    const std::uint32_t rb = segments.find(static_cast<std::uint32_t>(key & 0xffffffffu));
    if (ra == rb) continue;
    const auto apart = [&](std::uint32_t from, std::uint32_t to) {
      for (std::uint32_t other : rejected_by_root[from]) {
        if (segments.find(other) == to) return true;
      }
      return false;
    };
    if (apart(ra, rb) || apart(rb, ra)) continue;
    segments.join(ra, rb);
    const std::uint32_t root = segments.find(ra);
    auto& kept = rejected_by_root[root];
    auto& gone = rejected_by_root[root == ra ? rb : ra];
    kept.insert(kept.end(), gone.begin(), gone.end());
    gone.clear();
  }

  // In a depth image, segments that local convexity joined through one path although two of
  // their patches meet concavely are cut along the flat one's plane (concave_cuts.hpp).
  if (depth_image) {
    std::vector<std::uint32_t> group(static_cast<std::size_t>(patches));
    for (std::uint32_t p = 0; p < static_cast<std::uint32_t>(patches); ++p) group[p] = segments.find(p);
    std::vector<char> surface(g.size(), 0);
    for (std::uint32_t n = 0; n < g.size(); ++n) surface[n] = patch[n] >= 0 && origin[n] == n;
    const std::int32_t before = patches;
    group = cut_at_concave_faces(g, patch, surface, patches, std::move(group), pairs_of(junctions),
                                 [&](const std::vector<std::int32_t>& labels) { return pairs_of(judge_junctions(labels)); },
                                 cfg);
    // A split patch's pieces have junctions of their own, which the small segments below go by.
    if (patches != before) junctions = judge_junctions(patch);
    UnionFind cut(static_cast<std::size_t>(patches));
    std::unordered_map<std::uint32_t, std::uint32_t> first_of_group;
    for (std::uint32_t p = 0; p < static_cast<std::uint32_t>(patches); ++p) {
      const auto it = first_of_group.emplace(group[p], p).first;
      cut.join(it->second, p);
    }
    segments = cut;
  }

  // Small segments (edge slivers, noise) join the neighbour they share most edges with.
  std::vector<std::size_t> size(static_cast<std::size_t>(patches), 0);
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (patch[n] >= 0) ++size[segments.find(static_cast<std::uint32_t>(patch[n]))];
  }
  std::unordered_map<std::uint64_t, std::uint32_t> shared;
  for (const auto& [key, j] : junctions) {
    const std::uint32_t a = segments.find(static_cast<std::uint32_t>(key >> 32));
    const std::uint32_t b = segments.find(static_cast<std::uint32_t>(key & 0xffffffffu));
    if (a != b) shared[pair_key(a, b)] += j.total;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> best(static_cast<std::size_t>(patches), {0u, 0u});
  std::vector<char> has_best(static_cast<std::size_t>(patches), 0);
  for (const auto& [key, edges] : shared) {
    const auto a = static_cast<std::uint32_t>(key >> 32);
    const auto b = static_cast<std::uint32_t>(key & 0xffffffffu);
    for (const auto& [small, other] : {std::pair{a, b}, std::pair{b, a}}) {
      if (static_cast<std::int64_t>(size[small]) >= cfg.min_object_nodes) continue;
      if (!has_best[small] || edges > best[small].second) {
        best[small] = {other, edges};
        has_best[small] = 1;
      }
    }
  }
  for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(patches); ++s) {
    if (has_best[s]) segments.join(s, best[s].first);
  }

  std::vector<std::int32_t> out(g.size(), -1);
  std::unordered_map<std::uint32_t, std::int32_t> dense;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (patch[n] < 0) continue;
    const std::uint32_t root = segments.find(static_cast<std::uint32_t>(patch[n]));
    const auto it = dense.emplace(root, static_cast<std::int32_t>(dense.size())).first;
    out[n] = it->second;
  }
  return out;
}

}  // namespace cloudshape::segment
