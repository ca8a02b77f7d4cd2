#include "geometry/voxel_grid.hpp"

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <optional>

#include "geometry/detail/flat_hash.hpp"
#include "geometry/grid_neighbours.hpp"
#include "geometry/kdtree.hpp"

namespace cloudshape::geometry {
namespace {

constexpr std::size_t kGridFrom = 50000;

// 21 bits per axis (one voxel of margin each side for the neighbour test). A denormal voxel
// (inv = inf) or coordinates whose differences overflow give no grid (found by fuzz_ingest:
// 0 * inf = NaN would be cast to an integer below).
bool grid_fits(const Bounds& b, double inv) {
  const Eigen::Vector3d extent = (b.max - b.min) * inv;
  return std::isfinite(inv) && extent.allFinite() && extent.maxCoeff() < double((1 << 21) - 3);
}

// A voxel's coordinates, floor((p - b.min) * inv) on each axis: in [0, 2^21 - 3) once grid_fits
// (p lies in b), where converting to a signed integer gives what the unsigned keys took, in fewer
// instructions.
struct VoxelOf {
  Point min;
  double inv;
  std::array<std::int64_t, 3> operator()(const Point& p) const {
    const Eigen::Vector3d q = (p - min) * inv;
    return {static_cast<std::int64_t>(q.x()), static_cast<std::int64_t>(q.y()), static_cast<std::int64_t>(q.z())};
  }
};

// The voxels along each axis, with `margin` more either side, when a dense array over all of
// them has at most `max_cells` entries (then an array indexed by cell replaces the hash map, the
// same voxels found in the same order); empty otherwise.
std::array<std::uint64_t, 3> dense_dims(const Bounds& b, double inv, std::uint64_t margin, double max_cells) {
  const Eigen::Vector3d extent = (b.max - b.min) * inv;
  std::array<std::uint64_t, 3> dims{};
  double cells = 1.0;
  for (int a = 0; a < 3; ++a) {
    dims[a] = static_cast<std::uint64_t>(extent[a]) + 1 + 2 * margin;
    cells *= static_cast<double>(dims[a]);
  }
  if (!(cells <= max_cells)) dims = {};
  return dims;
}

// Whether voxel `c` lies in the dense array of `dims` (with `margin` either side): always, when the
// bounds given are the points' own box, as the header asks; a wrong box falls back to the map
// instead of indexing outside the array.
bool in_dense(const std::array<std::int64_t, 3>& c, const std::array<std::uint64_t, 3>& dims, std::uint64_t margin) {
  for (int a = 0; a < 3; ++a) {
    if (!(static_cast<std::uint64_t>(c[a]) < dims[a] - 2 * margin)) return false;
  }
  return true;
}

// bounding_box's fold over points[begin], points[begin + stride], ... before `end`, from the
// first of them.
Bounds bounds_of_range(const PointList& points, std::size_t begin, std::size_t end, std::size_t stride) {
  Bounds b;
  // x and y as one packet, z alone: what cwiseMin and cwiseMax of whole points give (std::min's
  // operand order both ways, signed zeros included), without Eigen's unaligned tail per point.
  Eigen::Vector2d lo_xy = points[begin].head<2>(), hi_xy = lo_xy;
  double lo_z = points[begin].z(), hi_z = lo_z;
  for (std::size_t i = begin; i < end; i += stride) {
    const Point& p = points[i];
    lo_xy = lo_xy.cwiseMin(p.head<2>());
    hi_xy = hi_xy.cwiseMax(p.head<2>());
    lo_z = std::min(lo_z, p.z());
    hi_z = std::max(hi_z, p.z());
  }
  b.min = Point(lo_xy.x(), lo_xy.y(), lo_z);
  b.max = Point(hi_xy.x(), hi_xy.y(), hi_z);
  return b;
}

// Sampled points a block of the parallel fold takes.
constexpr std::size_t kBoundsBlock = std::size_t{1} << 17;

}  // namespace

Bounds bounding_box(const PointList& points, std::size_t stride, parallel::ThreadPool* pool) {
  if (points.empty()) return Bounds{};
  const std::size_t sampled = (points.size() - 1) / stride + 1;
  if (pool == nullptr || sampled <= kBoundsBlock) return bounds_of_range(points, 0, points.size(), stride);
  // Each block's fold keeps the first least and greatest value it meets (the operand order
  // above), and so does the fold of the blocks' results in block order: the serial answer.
  std::vector<Bounds> block((sampled + kBoundsBlock - 1) / kBoundsBlock);
  parallel::for_blocks(pool, sampled, kBoundsBlock, [&](std::size_t first, std::size_t last) {
    block[first / kBoundsBlock] = bounds_of_range(points, first * stride, std::min(points.size(), last * stride), stride);
  });
  Bounds b = block.front();
  for (std::size_t k = 1; k < block.size(); ++k) {
    b.min = b.min.cwiseMin(block[k].min);
    b.max = b.max.cwiseMax(block[k].max);
  }
  return b;
}

namespace {

struct VoxelSum {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::uint32_t count = 0;
  std::uint64_t key = 0;
};

// Whether fewer than `min_occupied` of a voxel's 26 neighbours are occupied, `occupied(dx, dy, dz)`
// telling for each offset; the search stops once that many are found.
template <class Occupied>
bool lonely_voxel(int min_occupied, const Occupied& occupied) {
  int found = 0;
  for (int dx = -1; dx <= 1 && found < min_occupied; ++dx)
    for (int dy = -1; dy <= 1 && found < min_occupied; ++dy)
      for (int dz = -1; dz <= 1 && found < min_occupied; ++dz)
        if ((dx || dy || dz) && occupied(dx, dy, dz)) ++found;
  return found < min_occupied;
}

// The voxels of `points` in the order their first point comes, each with its sum, count and
// key; `lonely` marks those with fewer than `min_occupied_neighbours` occupied among their 26
// neighbours (only whether that many are reached matters: the search stops there). The hash map.
std::vector<VoxelSum> sum_voxels_in_map(const PointList& points, const VoxelOf& voxel_of,
                                        int min_occupied_neighbours, std::vector<char>& lonely) {
  detail::CellMap slot(points.size() / 4 + 16);
  std::vector<VoxelSum> acc;
  acc.reserve(points.size() / 4 + 16);
  for (const Point& p : points) {
    const auto c = voxel_of(p);
    const std::uint64_t key = detail::cell_key(c[0] + 1, c[1] + 1, c[2] + 1);
    bool inserted = false;
    const std::uint32_t s = slot.find_or_insert(key, static_cast<std::uint32_t>(acc.size()), inserted);
    if (inserted) {
      acc.emplace_back();
      acc.back().key = key;
    }
    acc[s].sum += p;
    ++acc[s].count;
  }
  lonely.assign(acc.size(), 0);
  if (min_occupied_neighbours <= 0) return acc;
  for (std::size_t v = 0; v < acc.size(); ++v) {
    const auto [ix, iy, iz] = detail::cell_coords(acc[v].key);
    lonely[v] = lonely_voxel(
        min_occupied_neighbours, [&, ix = ix, iy = iy, iz = iz](int dx, int dy, int dz) {
          return slot.find(detail::cell_key(ix + dx, iy + dy, iz + dz)) != detail::CellMap::kAbsent;
        });
  }
  return acc;
}

// The same over a dense array of `dims` cells (one of margin either side), `key` the cell's index;
// none when a point lies outside the array (bounds that are not the points' box).
std::optional<std::vector<VoxelSum>> sum_voxels_in_array(const PointList& points, const VoxelOf& voxel_of,
                                                         const std::array<std::uint64_t, 3>& dims,
                                                         int min_occupied_neighbours, std::vector<char>& lonely) {
  const std::uint64_t ny = dims[1], nz = dims[2];
  std::vector<std::uint32_t> slot(dims[0] * ny * nz, detail::CellMap::kAbsent);
  std::vector<VoxelSum> acc;
  acc.reserve(points.size() / 4 + 16);
  for (const Point& p : points) {
    const auto c = voxel_of(p);
    if (!in_dense(c, dims, 1)) return std::nullopt;
    const std::uint64_t cell = ((static_cast<std::uint64_t>(c[0]) + 1) * ny + static_cast<std::uint64_t>(c[1]) + 1) * nz +
                               static_cast<std::uint64_t>(c[2]) + 1;
    std::uint32_t& s = slot[cell];
    if (s == detail::CellMap::kAbsent) {
      s = static_cast<std::uint32_t>(acc.size());
      acc.emplace_back();
      acc.back().key = cell;
    }
    VoxelSum& v = acc[s];
    v.sum += p;
    ++v.count;
  }
  lonely.assign(acc.size(), 0);
  if (min_occupied_neighbours <= 0) return acc;
  const std::int64_t step[3] = {static_cast<std::int64_t>(ny * nz), static_cast<std::int64_t>(nz), 1};
  for (std::size_t v = 0; v < acc.size(); ++v) {
    const std::int64_t cell = static_cast<std::int64_t>(acc[v].key);
    lonely[v] = lonely_voxel(min_occupied_neighbours, [&](int dx, int dy, int dz) {
      return slot[static_cast<std::size_t>(cell + dx * step[0] + dy * step[1] + dz * step[2])] !=
             detail::CellMap::kAbsent;
    });
  }
  return acc;
}

}  // namespace

PointList voxel_grid_downsample(const PointList& points, double voxel_size,
                                int min_occupied_neighbours, std::size_t* isolated, const Bounds* bounds) {
  if (isolated) *isolated = 0;
  if (!(voxel_size > 0.0) || points.empty()) return points;
  const Bounds b = bounds ? *bounds : bounding_box(points);
  const double inv = 1.0 / voxel_size;
  if (!grid_fits(b, inv)) return points;
  const VoxelOf voxel_of{b.min, inv};
  // An array of at most two cells a point (8 bytes) takes about the map's memory (6 to 12 bytes a
  // point) and no hashing.
  const auto dims = dense_dims(b, inv, 1, 2.0 * static_cast<double>(points.size()));
  std::vector<char> lonely;
  std::optional<std::vector<VoxelSum>> in_array;
  if (dims[0] > 0) in_array = sum_voxels_in_array(points, voxel_of, dims, min_occupied_neighbours, lonely);
  const std::vector<VoxelSum> acc =
      in_array ? std::move(*in_array) : sum_voxels_in_map(points, voxel_of, min_occupied_neighbours, lonely);
  std::size_t lonely_count = 0;
  for (char l : lonely) lonely_count += static_cast<std::size_t>(l);
  // Many lonely voxels mean the grid is finer than the cloud's own sampling, not that
  // the cloud is full of outliers: then nothing is dropped.
  if (lonely_count * 4 > acc.size()) std::fill(lonely.begin(), lonely.end(), 0), lonely_count = 0;
  if (isolated) *isolated = lonely_count;
  PointList out;
  out.reserve(acc.size() - lonely_count);
  for (std::size_t v = 0; v < acc.size(); ++v)
    if (!lonely[v]) out.push_back(acc[v].sum / static_cast<double>(acc[v].count));
  return out;
}

namespace {

// Bits a point the occupancy arrays may take in all: 8 bytes (a map takes 24 or more).
constexpr double kMaxBitsPerPoint = 64.0;

// The occupied voxels of points[0], points[stride], ... (n of them) as bits of a dense array of
// `dims` cells, voxel c at cell c + margin on each axis, and how many are set. A large cloud's
// points in one part per thread, each setting the bits of its own array, joined into the first:
// the same bits, whatever the parts. Nothing when a point lies outside the array.
std::optional<std::pair<std::vector<std::uint64_t>, std::uint64_t>> occupancy_bits(
    const PointList& points, std::size_t n, std::size_t stride, const VoxelOf& voxel_of,
    const std::array<std::uint64_t, 3>& dims, std::uint64_t margin, parallel::ThreadPool* pool) {
  const std::uint64_t cells = dims[0] * dims[1] * dims[2];
  // An array per part, as many parts as fit kMaxBitsPerPoint bits a point in all (one at least).
  const double affordable = kMaxBitsPerPoint * static_cast<double>(n) /
                            static_cast<double>(std::max<std::uint64_t>(1, cells));
  const std::size_t threads =
      pool != nullptr && n >= kBoundsBlock
          ? std::clamp<std::size_t>(static_cast<std::size_t>(affordable), 1, pool->size())
          : 1;
  const std::size_t per_part = (n + threads - 1) / threads;
  const std::size_t parts = (n + per_part - 1) / per_part;  // for_blocks' count: at most `threads`
  std::vector<std::vector<std::uint64_t>> bits(parts);
  std::vector<std::uint64_t> set(parts, 0);  // bits each part set first: its own count
  std::vector<char> inside(parts, 1);
  parallel::for_blocks(pool, n, per_part, [&](std::size_t first, std::size_t last) {
    std::vector<std::uint64_t>& own = bits[first / per_part];
    own.assign((cells + 63) / 64, 0);
    // Locals, not the captures: kept in registers across the points.
    const VoxelOf to_voxel = voxel_of;
    const std::array<std::uint64_t, 3> d = dims;
    const std::uint64_t m = margin;
    std::uint64_t* const words = own.data();
    std::uint64_t count = 0;
    for (std::size_t s = first; s < last; ++s) {
      const auto c = to_voxel(points[s * stride]);
      if (!in_dense(c, d, m)) {
        inside[first / per_part] = 0;
        return;
      }
      const std::uint64_t cell =
          ((static_cast<std::uint64_t>(c[0]) + m) * d[1] + static_cast<std::uint64_t>(c[1]) + m) *
              d[2] +
          static_cast<std::uint64_t>(c[2]) + m;
      std::uint64_t& word = words[cell >> 6];
      const std::uint64_t bit = std::uint64_t{1} << (cell & 63);
      count += (word & bit) == 0 ? 1 : 0;
      word |= bit;
    }
    set[first / per_part] = count;
  });
  if (std::find(inside.begin(), inside.end(), 0) != inside.end()) return std::nullopt;
  if (parts == 1) return std::make_pair(std::move(bits.front()), set.front());
  std::uint64_t occupied = 0;
  std::vector<std::uint64_t>& joined = bits.front();
  for (std::size_t w = 0; w < joined.size(); ++w) {
    for (std::size_t k = 1; k < parts; ++k) joined[w] |= bits[k][w];
    occupied += std::bitset<64>(joined[w]).count();
  }
  return std::make_pair(std::move(joined), occupied);
}

}  // namespace

std::size_t count_occupied_voxels(const PointList& points, double voxel_size, const Bounds* bounds,
                                  std::size_t stride, parallel::ThreadPool* pool) {
  const std::size_t n = points.empty() ? 0 : (points.size() - 1) / stride + 1;
  if (!(voxel_size > 0.0) || points.empty()) return n;
  const Bounds b = bounds ? *bounds : bounding_box(points, stride, pool);
  const double inv = 1.0 / voxel_size;
  // The same keys and the same validity as voxel_grid_downsample's.
  if (!grid_fits(b, inv)) return n;
  const VoxelOf voxel_of{b.min, inv};
  // A bit per voxel while that is at most kMaxBitsPerPoint a point.
  const auto dims = dense_dims(b, inv, 0, kMaxBitsPerPoint * static_cast<double>(n));
  if (dims[0] > 0) {
    if (const auto bits = occupancy_bits(points, n, stride, voxel_of, dims, 0, pool))
      return bits->second;
  }
  // Room for a voxel per point: the finest voxel of a search often holds one or two points, and
  // a map that grows rehashes every key it has.
  detail::CellMap slot(n + 16);
  std::uint64_t occupied = 0;
  for (std::size_t i = 0; i < points.size(); i += stride) {
    const auto c = voxel_of(points[i]);
    bool inserted = false;
    slot.find_or_insert(detail::cell_key(c[0], c[1], c[2]), static_cast<std::uint32_t>(occupied),
                        inserted);
    occupied += inserted ? 1 : 0;
  }
  return occupied;
}

std::optional<std::size_t> downsampled_size(const PointList& points, double voxel_size,
                                            int min_occupied_neighbours, const Bounds* bounds,
                                            parallel::ThreadPool* pool) {
  if (!(voxel_size > 0.0) || points.empty()) return points.size();
  const Bounds b = bounds ? *bounds : bounding_box(points, 1, pool);
  const double inv = 1.0 / voxel_size;
  if (!grid_fits(b, inv)) return points.size();
  // A bit per voxel with one of margin either side (the neighbours need no bounds test), while
  // that is at most kMaxBitsPerPoint a point.
  const auto dims = dense_dims(b, inv, 1, kMaxBitsPerPoint * static_cast<double>(points.size()));
  const auto bits =
      dims[0] > 0 ? occupancy_bits(points, points.size(), 1, VoxelOf{b.min, inv}, dims, 1, pool)
                  : std::nullopt;
  if (!bits) return std::nullopt;
  const auto& [words, occupied] = *bits;
  if (min_occupied_neighbours <= 0) return occupied;
  // voxel_grid_downsample's isolated voxels: fewer occupied among their 26 neighbours.
  const std::int64_t step[3] = {static_cast<std::int64_t>(dims[1] * dims[2]),
                                static_cast<std::int64_t>(dims[2]), 1};
  const auto occupied_at = [&words](std::int64_t cell) {
    return (words[static_cast<std::size_t>(cell) >> 6] >> (cell & 63)) & 1;
  };
  std::uint64_t lonely = 0;
  for (std::size_t w = 0; w < words.size(); ++w) {
    for (std::uint64_t rest = words[w]; rest != 0; rest &= rest - 1) {
      const auto cell =
          static_cast<std::int64_t>(w * 64 + static_cast<std::size_t>(__builtin_ctzll(rest)));
      const auto occupied_by = [&](int dx, int dy, int dz) {
        return occupied_at(cell + dx * step[0] + dy * step[1] + dz * step[2]) != 0;
      };
      if (lonely_voxel(min_occupied_neighbours, occupied_by)) ++lonely;
    }
  }
  // As there: many isolated voxels mean a grid finer than the sampling, and none is dropped.
  if (lonely * 4 > occupied) lonely = 0;
  return occupied - lonely;
}

namespace {

std::vector<std::uint32_t> spread_sample(std::size_t size, std::size_t max_samples) {
  const std::size_t step = std::max<std::size_t>(1, size / std::max<std::size_t>(1, max_samples));
  std::vector<std::uint32_t> sample;
  for (std::size_t i = 0; i < size; i += step) sample.push_back(static_cast<std::uint32_t>(i));
  return sample;
}

double mean_over_grid(const PointList& points, const std::vector<std::uint32_t>& sample, parallel::ThreadPool* pool,
                      const Bounds* bounds) {
  double sum = 0.0;
  for (double d : nearest_other_distances(points, sample, pool, bounds)) sum += d;
  return sum / static_cast<double>(sample.size());
}

// The searches in blocks on the pool, the sum in sample order: the same value for any pool.
double mean_over_tree(const KdTree& tree, const std::vector<std::uint32_t>& sample, parallel::ThreadPool* pool) {
  std::vector<double> distance(sample.size());
  parallel::for_blocks(pool, sample.size(), 512, [&](std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) distance[s] = std::sqrt(tree.nearest_other_sq_dist(sample[s]));
  });
  double sum = 0.0;
  for (double d : distance) sum += d;
  return sum / static_cast<double>(sample.size());
}

}  // namespace

// The grid's one binning pass beats a kd-tree's sorting on big clouds only; both are exact.
double mean_nearest_neighbour_distance(const PointList& points, std::size_t max_samples, parallel::ThreadPool* pool,
                                       const Bounds* bounds) {
  if (points.size() < 2) return 0.0;
  const std::vector<std::uint32_t> sample = spread_sample(points.size(), max_samples);
  if (points.size() > kGridFrom) return mean_over_grid(points, sample, pool, bounds);
  return mean_over_tree(KdTree(points), sample, pool);
}

double mean_nearest_neighbour_distance(const KdTree& tree, std::size_t max_samples, parallel::ThreadPool* pool) {
  const PointList& points = tree.points();
  if (points.size() < 2) return 0.0;
  const std::vector<std::uint32_t> sample = spread_sample(points.size(), max_samples);
  if (points.size() > kGridFrom) return mean_over_grid(points, sample, pool, nullptr);
  return mean_over_tree(tree, sample, pool);
}

}  // namespace cloudshape::geometry
