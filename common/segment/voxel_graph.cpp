#include "segment/neighbour_graph.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/detail/flat_hash.hpp"
#include "geometry/grid_neighbours.hpp"
#include "geometry/voxel_grid.hpp"
#include "segment/detail/graph_moments.hpp"
#include "segment/line_neighbourhoods.hpp"

namespace cloudshape::segment {

using detail::along_a_line;
using detail::fill_spacing;
using detail::kNodesPerBlock;
using detail::Moments;
using detail::normal_of;

namespace {

// A voxel key packs 21 bits per axis: an axis holds at most this many cells, with room to spare.
constexpr double kMaxCellsPerAxis = 1 << 20;

// The CSR adjacency with the extra (symmetric) edges added, each neighbour listed once.
void add_edges(NeighbourGraph& g, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
  if (edges.empty()) return;
  std::vector<std::vector<std::uint32_t>> extra(g.size());
  for (const auto& [a, b] : edges) {
    extra[a].push_back(b);
    extra[b].push_back(a);
  }
  std::vector<std::uint32_t> begin(g.size() + 1, 0), adjacency;
  adjacency.reserve(g.adjacency.size() + 2 * edges.size());
  std::vector<std::uint32_t> near;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    near.assign(g.adjacency.begin() + g.adjacency_begin[n], g.adjacency.begin() + g.adjacency_begin[n + 1]);
    near.insert(near.end(), extra[n].begin(), extra[n].end());
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    adjacency.insert(adjacency.end(), near.begin(), near.end());
    begin[n + 1] = static_cast<std::uint32_t>(adjacency.size());
  }
  g.adjacency_begin.swap(begin);
  g.adjacency.swap(adjacency);
}

// finest_voxel of points within `box`.
double finest_in(const PointList& points, const geometry::Bounds& box, parallel::ThreadPool* pool) {
  // Three times the sampling: 26-neighbour voxels must connect a surface's points where its
  // sampling thins out. The extent bounds a cell index without squares, which underflow for a
  // cloud of 1e-253 (found by fuzzing).
  return std::max(3.0 * geometry::mean_nearest_neighbour_distance(points, 4000, pool, &box),
                  (box.max - box.min).maxCoeff() / kMaxCellsPerAxis);
}

// budget_in for cfg.voxel_target_nodes and for `fewer` (a coarser budget) at once.
std::pair<double, double> budgets_in(const PointList& points, const geometry::Bounds& box,
                                     const config::SegmentConfig& cfg, std::int64_t fewer,
                                     parallel::ThreadPool* pool) {
  // Never finer than the scene-wide voxel (target_nodes over the bounding box, at least
  // finest_in), and coarser only where the surface holds more than voxel_target_nodes cells at
  // that voxel: a densely sampled solid gets fewer nodes, a scene's empty space (a small solid far
  // from the rest, a lidar's sphere among walls) coarsens nothing (remainder_graph scales by nodes
  // kept too).
  const double finest = finest_in(points, box, pool);
  const double nodes = static_cast<double>(std::max<std::int64_t>(1, cfg.target_nodes));
  const double scene = std::max(box.diagonal() / std::sqrt(nodes), finest);
  const double occupied = static_cast<double>(geometry::count_occupied_voxels(points, scene, &box, 1, pool));
  const auto for_target = [&](std::int64_t target) {
    return scene * std::max(1.0, std::sqrt(occupied / static_cast<double>(std::max<std::int64_t>(1, target))));
  };
  const double voxel = for_target(cfg.voxel_target_nodes);
  return {voxel, std::max(voxel, for_target(fewer))};
}

double budget_in(const PointList& points, const geometry::Bounds& box, const config::SegmentConfig& cfg,
                 parallel::ThreadPool* pool) {
  return budgets_in(points, box, cfg, cfg.voxel_target_nodes, pool).first;
}

// build_voxel_graph of points within `box` (their bounding box), at least one point.
NeighbourGraph build_in(const PointList& points, const geometry::Bounds& box, double voxel,
                        std::optional<std::int64_t> max_nodes, const config::SegmentConfig& cfg,
                        parallel::ThreadPool* pool);

}  // namespace

double finest_voxel(const PointList& points, parallel::ThreadPool* pool) {
  return points.empty() ? 0.0 : finest_in(points, geometry::bounding_box(points, 1, pool), pool);
}

double budget_voxel(const PointList& points, const config::SegmentConfig& cfg, parallel::ThreadPool* pool) {
  return points.empty() ? 0.0 : budget_in(points, geometry::bounding_box(points, 1, pool), cfg, pool);
}

std::pair<double, double> budget_voxels(const PointList& points, const config::SegmentConfig& cfg,
                                        std::int64_t fewer, parallel::ThreadPool* pool,
                                        const geometry::Bounds* bounds) {
  if (points.empty()) return {0.0, 0.0};
  return budgets_in(points, bounds ? *bounds : geometry::bounding_box(points, 1, pool), cfg, fewer,
                    pool);
}

// One bounding box for the budget, its resolution bound and the binning; target_nodes stays the
// cap (budget_in's voxel holds about voxel_target_nodes cells, or fewer).
NeighbourGraph build_voxel_graph(const PointList& points, const config::SegmentConfig& cfg,
                                 parallel::ThreadPool* pool) {
  if (points.empty()) return build_voxel_graph(points, 0.0, cfg.target_nodes, cfg, pool);
  const geometry::Bounds box = geometry::bounding_box(points, 1, pool);
  return build_in(points, box, budget_in(points, box, cfg, pool), cfg.target_nodes, cfg, pool);
}

NeighbourGraph build_voxel_graph(const PointList& points, double voxel,
                                 std::optional<std::int64_t> max_nodes,
                                 const config::SegmentConfig& cfg, parallel::ThreadPool* pool,
                                 const geometry::Bounds* bounds) {
  if (points.empty()) {
    NeighbourGraph g;
    g.adjacency_begin.assign(1, 0);
    return g;
  }
  return build_in(points, bounds ? *bounds : geometry::bounding_box(points, 1, pool), voxel,
                  max_nodes, cfg, pool);
}

namespace {

// Points from which build_in works out their cells on the pool before numbering the voxels.
constexpr std::size_t kPackedFrom = 200000;

// A voxel's node: an array over the bounding box's voxels where that holds at most
// kArrayVoxelsPerPoint a point (an index instead of a hash), else the hash map of packed keys
// (21 bits an axis). The same nodes either way: the array only where no coordinate reaches 21 bits.
class VoxelNodes {
 public:
  static constexpr std::uint32_t kOutside = geometry::detail::CellMap::kAbsent - 1;
  static constexpr double kArrayVoxelsPerPoint = 2.0;

  static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
    return geometry::detail::cell_key(c[0], c[1], c[2]);
  }

  // The map alone.
  explicit VoxelNodes(std::size_t expected) : map_(expected) {}

  // The array where `extent` (the box in voxels) allows, with a voxel to spare along each axis.
  VoxelNodes(const Eigen::Vector3d& extent, std::size_t points, std::size_t expected) : map_(16) {
    double cells = 1.0;
    for (int a = 0; a < 3; ++a) {
      if (!(extent[a] >= 0.0 && extent[a] < double((1 << 21) - 4))) cells = -1.0;
      if (cells < 0.0) break;
      dims_[a] = static_cast<std::int64_t>(extent[a]) + 2;
      cells *= static_cast<double>(dims_[a]);
    }
    if (cells > 0.0 && cells <= kArrayVoxelsPerPoint * static_cast<double>(points)) {
      slot_.assign(static_cast<std::size_t>(cells), geometry::detail::CellMap::kAbsent);
    } else {
      map_ = geometry::detail::CellMap(expected);
    }
  }

  // The node of voxel c, `value` if it is new; kOutside if the array does not hold c (a point
  // outside the bounds the array was sized for: then bin again with the map).
  std::uint32_t find_or_insert(const std::array<std::int64_t, 3>& c, std::uint32_t value, bool& inserted) {
    if (slot_.empty()) return map_.find_or_insert(key(c), value, inserted);
    if (!holds(c)) return kOutside;
    std::uint32_t& s = slot_[index(c)];
    inserted = s == geometry::detail::CellMap::kAbsent;
    if (inserted) s = value;
    return s;
  }

  std::uint32_t find(const std::array<std::int64_t, 3>& c) const {
    if (slot_.empty()) return map_.find(key(c));
    return holds(c) ? slot_[index(c)] : geometry::detail::CellMap::kAbsent;
  }

 private:
  bool holds(const std::array<std::int64_t, 3>& c) const {
    for (int a = 0; a < 3; ++a) {
      if (static_cast<std::uint64_t>(c[a]) >= static_cast<std::uint64_t>(dims_[a])) return false;
    }
    return true;
  }
  std::size_t index(const std::array<std::int64_t, 3>& c) const {
    return static_cast<std::size_t>((c[0] * dims_[1] + c[1]) * dims_[2] + c[2]);
  }

  std::array<std::int64_t, 3> dims_{};
  std::vector<std::uint32_t> slot_;
  geometry::detail::CellMap map_;
};

NeighbourGraph build_in(const PointList& points, const geometry::Bounds& box, double voxel,
                        std::optional<std::int64_t> max_nodes, const config::SegmentConfig& cfg,
                        parallel::ThreadPool* pool) {
  NeighbourGraph g;
  g.node_of_point.assign(points.size(), kNoNode);
  const Point origin = box.min;
  // A budget of nodes caps the voxel count (1.3 times it); none: every voxel the points fill (a
  // voxel never finer than finest_voxel fills no more than there are points).
  const double target = static_cast<double>(std::max<std::int64_t>(1, max_nodes.value_or(0)));
  const double cap = max_nodes ? 1.3 * target : static_cast<double>(points.size());
  voxel = std::max(voxel, 1e-300);

  using Key = std::uint64_t;
  // p - origin >= 0 (origin is the points' minimum), so truncation is the floor.
  const auto cell_of = [&](const Point& p, double v) {
    const Eigen::Vector3d c = (p - origin) / v;
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(c.x()), static_cast<std::int64_t>(c.y()),
                                       static_cast<std::int64_t>(c.z())};
  };
  // Node ids in order of first appearance; each point's node kept from the pass that found them.
  // A large cloud's cells are worked out first, in blocks on the pool (packed as the map's keys,
  // lossless below 2^21 a coordinate; otherwise each point's as it comes).
  std::vector<Key> keys;
  std::vector<std::uint32_t> node;
  std::vector<Key> packed;
  const auto pack_cells = [&](double v) {
    constexpr std::size_t kPointsPerBlock = 65536;
    packed.resize(points.size());
    std::vector<char> fits((points.size() + kPointsPerBlock - 1) / kPointsPerBlock, 1);
    parallel::for_blocks(pool, points.size(), kPointsPerBlock, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const auto c = cell_of(points[i], v);
        if (static_cast<std::uint64_t>(c[0] | c[1] | c[2]) >= (std::uint64_t{1} << 21)) {
          fits[begin / kPointsPerBlock] = 0;
          return;
        }
        packed[i] = VoxelNodes::key(c);
      }
    });
    if (std::find(fits.begin(), fits.end(), 0) != fits.end()) packed.clear();
  };
  // `cell_at(i)`: point i's cell, worked out or unpacked (one loop each, no test per point).
  const auto bin_cells = [&](const auto& cell_at, VoxelNodes& voxels) {
    keys.clear();
    node.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::array<std::int64_t, 3> c = cell_at(i);
      bool inserted = false;
      node[i] = voxels.find_or_insert(c, static_cast<std::uint32_t>(keys.size()), inserted);
      if (node[i] == VoxelNodes::kOutside) return false;
      if (inserted) {
        keys.push_back(VoxelNodes::key(c));
        if (static_cast<double>(keys.size()) > cap) return true;
      }
    }
    return true;
  };
  const auto bin_in = [&](double v, VoxelNodes& voxels) {
    if (!packed.empty()) {
      return bin_cells([&](std::size_t i) { return geometry::detail::cell_coords(packed[i]); },
                       voxels);
    }
    return bin_cells([&](std::size_t i) { return cell_of(points[i], v); }, voxels);
  };
  const auto bin = [&](double v) {
    packed.clear();
    if (pool != nullptr && pool->size() > 1 && points.size() >= kPackedFrom) pack_cells(v);
    const std::size_t expected = std::min<std::size_t>(points.size(), static_cast<std::size_t>(cap) + 1);
    VoxelNodes voxels((box.max - box.min) / v, points.size(), expected);
    if (!bin_in(v, voxels)) {
      voxels = VoxelNodes(expected);
      bin_in(v, voxels);
    }
    return voxels;
  };
  // Grow the voxel until the node budget holds; a surface fills voxels with the square of the edge.
  VoxelNodes voxels = bin(voxel);
  for (int attempt = 1; attempt < 40 && static_cast<double>(keys.size()) > cap; ++attempt) {
    voxel *= 1.25;
    voxels = bin(voxel);
  }
  const std::size_t nodes = keys.size();
  g.nodes.assign(nodes, Point::Zero());
  std::vector<std::size_t> counts(nodes, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t n = node[i];
    g.node_of_point[i] = n;
    g.nodes[n] += points[i];
    ++counts[n];
  }
  for (std::size_t n = 0; n < g.size(); ++n) g.nodes[n] /= static_cast<double>(counts[n]);

  // Adjacency is symmetric: each voxel looks up only the 13 neighbours after it (in key order),
  // and each pair found is listed on both sides; rows are then sorted by node id.
  // Blocks of nodes find their pairs on the pool; the pairs are joined in block order.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> pairs_of_block((nodes + kNodesPerBlock - 1) / kNodesPerBlock);
  parallel::for_blocks(pool, nodes, kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    auto& found = pairs_of_block[begin / kNodesPerBlock];
    found.reserve((end - begin) * 6);
    for (std::size_t n = begin; n < end; ++n) {
      const auto [x, y, z] = geometry::detail::cell_coords(keys[n]);
      for (int dx = 0; dx <= 1; ++dx) {
        for (int dy = dx == 0 ? 0 : -1; dy <= 1; ++dy) {
          for (int dz = dx == 0 && dy == 0 ? 1 : -1; dz <= 1; ++dz) {
            if (y + dy < 0 || z + dz < 0) continue;
            const std::uint32_t m = voxels.find({x + dx, y + dy, z + dz});
            if (m != geometry::detail::CellMap::kAbsent) found.emplace_back(static_cast<std::uint32_t>(n), m);
          }
        }
      }
    }
  });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& found : pairs_of_block) pairs.insert(pairs.end(), found.begin(), found.end());
  g.adjacency_begin.assign(nodes + 1, 0);
  for (const auto& [a, b] : pairs) {
    ++g.adjacency_begin[a + 1];
    ++g.adjacency_begin[b + 1];
  }
  for (std::size_t n = 0; n < nodes; ++n) g.adjacency_begin[n + 1] += g.adjacency_begin[n];
  // The rows in pair order first; then read back node by node, each node appended to the rows
  // of its neighbours: the edges are symmetric, so every row comes out sorted (no sort).
  std::vector<std::uint32_t> unsorted(2 * pairs.size());
  {
    std::vector<std::uint32_t> next(g.adjacency_begin.begin(), g.adjacency_begin.end() - 1);
    for (const auto& [a, b] : pairs) {
      unsorted[next[a]++] = b;
      unsorted[next[b]++] = a;
    }
  }
  g.adjacency.resize(unsorted.size());
  {
    std::vector<std::uint32_t> next(g.adjacency_begin.begin(), g.adjacency_begin.end() - 1);
    for (std::uint32_t b = 0; b < nodes; ++b) {
      for (std::uint32_t e = g.adjacency_begin[b]; e < g.adjacency_begin[b + 1]; ++e) g.adjacency[next[unsorted[e]]++] = b;
    }
  }
  fill_spacing(g, voxel, pool);

  const std::size_t k = std::min<std::size_t>(g.size(), static_cast<std::size_t>(std::max<std::int64_t>(3, cfg.normal_neighbours)));
  // Nodes sit about a voxel apart on a surface: the k-th lies within sqrt(k / pi) voxels. A grid
  // cell of 0.6 sqrt(k) voxels costs the fewest distances plus wider searches on both thin
  // (noise-free) and thick (noisy) surfaces (callgrind, 100k-point boxes: 0.75 cost 1.2-1.4x
  // more, 0.5 0.8x on the noisy one but 2x on the thin one).
  std::vector<std::uint32_t> knn;
  geometry::all_nearest_neighbours(g.nodes, k, 0.6 * std::sqrt(static_cast<double>(k)) * voxel, knn, pool);
  g.normals.resize(g.size());
  g.curvature.resize(g.size());
  std::vector<char> linear(g.size(), 0);
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      Moments m;
      m.origin = g.nodes[n];
      for (std::size_t j = 0; j < k; ++j) m.add(g.nodes[knn[n * k + j]]);
      double spread = 1.0;
      normal_of(m, g.normals[n], g.curvature[n], &spread);
      linear[n] = m.count >= 3 && spread < cfg.line_spread ? 1 : 0;
    }
  });
  // A node whose voxel neighbours lie on a line through it (one on each side at least: a pair of
  // stray points is no ring) sits on one scan ring.
  std::vector<Eigen::Vector3d> line_of(g.size(), Eigen::Vector3d::Zero());
  // The eigenvalues alone tell the spread; the eigenvectors are computed only for the few on a line.
  parallel::for_blocks(pool, g.size(), kNodesPerBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t n = begin; n < end; ++n) {
      Moments m;
      m.origin = g.nodes[n];
      m.add(g.nodes[n]);
      g.for_neighbours(static_cast<std::uint32_t>(n), [&](std::uint32_t j) { m.add(g.nodes[j]); });
      if (!along_a_line(m, cfg.line_spread, line_of[n])) continue;
      if (!line_of[n].allFinite()) line_of[n].setZero();
    }
  });
  // The spacing stays that of the voxel neighbours (along a ring): the extra edges only join
  // rings into one surface.
  add_edges(g, widen_line_neighbourhoods(g.nodes, linear, line_of, cfg, g.normals, g.curvature));
  return g;
}

}  // namespace

}  // namespace cloudshape::segment
