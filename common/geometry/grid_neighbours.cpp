#include "geometry/grid_neighbours.hpp"

#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <limits>
#include <optional>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "geometry/detail/flat_hash.hpp"
#include "geometry/kdtree.hpp"
#include "geometry/voxel_grid.hpp"

namespace cloudshape::geometry {
namespace {

// Cell coordinates carry one cell of margin below and above, like voxel_grid_downsample's.
constexpr double kMaxCells = double((1 << 21) - 4);
// Rounding in a point's position within its cell, in cells: the bounds below give this away.
constexpr double kSlack = 1e-8;
// How much wider the cells of the second search for queries the first leaves open are: their
// nearest lies beyond one cell, mostly within two, and four keeps that search's blocks (and the
// points it must look at) few.
constexpr double kWiderCells = 4.0;

// The same sum, in the same order, as nanoflann's L2_Simple_Adaptor: equal distances to the bit.
double squared_distance(const Point& a, const Point& b) {
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double diff = a[i] - b[i];
    d2 += diff * diff;
  }
  return d2;
}

// Cubic cells of edge `cell` from `min`: a point's cell coordinates, with one cell of margin
// below, and how far it lies at least from any point beyond the cells round its own.
struct CellFrame {
  Point min = Point::Zero();
  double cell = 0.0;
  double inv = 0.0;

  std::array<std::int64_t, 3> coords(const Point& p) const {
    const Eigen::Vector3d q = (p - min) * inv;
    return {static_cast<std::int64_t>(q.x()) + 1, static_cast<std::int64_t>(q.y()) + 1,
            static_cast<std::int64_t>(q.z()) + 1};
  }

  // How far p is, at least, from any point outside the block of cells within `ring` of its own.
  double reach(const Point& p, std::int64_t ring) const {
    const Eigen::Vector3d q = (p - min) * inv;
    double margin = 1.0;
    for (int a = 0; a < 3; ++a) {
      const double f = q[a] - std::floor(q[a]);
      margin = std::min({margin, f, 1.0 - f});
    }
    return std::max(0.0, margin + static_cast<double>(ring) - kSlack) * cell;
  }
};

// The points binned into cubic cells: the members of each occupied cell in increasing index.
class Grid {
 public:
  Grid(const PointList& points, const Bounds& b, double cell) : map_(points.size() / 4 + 16) {
    frame_ = CellFrame{b.min, cell, 1.0 / cell};
    const Eigen::Vector3d extent = (b.max - b.min) * frame_.inv;
    valid_ = cell > 0.0 && std::isfinite(frame_.inv) && extent.allFinite() && extent.maxCoeff() < kMaxCells;
    if (!valid_) return;
    cell_of_.resize(points.size());
    std::vector<std::uint32_t> count;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto c = coords(points[i]);
      bool inserted = false;
      const std::uint32_t s = map_.find_or_insert(
          detail::cell_key(c[0], c[1], c[2]), static_cast<std::uint32_t>(count.size()), inserted);
      if (inserted) count.push_back(0);
      ++count[s];
      cell_of_[i] = s;
    }
    begin_.assign(count.size() + 1, 0);
    for (std::size_t s = 0; s < count.size(); ++s) begin_[s + 1] = begin_[s] + count[s];
    members_.resize(points.size());
    std::vector<std::uint32_t> next(begin_.begin(), begin_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) members_[next[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }

  bool valid() const { return valid_; }
  std::size_t cells() const { return begin_.empty() ? 0 : begin_.size() - 1; }

  std::array<std::int64_t, 3> coords(const Point& p) const { return frame_.coords(p); }
  double reach(const Point& p, std::int64_t ring) const { return frame_.reach(p, ring); }

  // Calls f(member index) for every point in the cells exactly `ring` cells (Chebyshev) from c.
  template <class F>
  void for_ring(const std::array<std::int64_t, 3>& c, std::int64_t ring, F&& f) const {
    for (std::int64_t dx = -ring; dx <= ring; ++dx) {
      for (std::int64_t dy = -ring; dy <= ring; ++dy) {
        for (std::int64_t dz = -ring; dz <= ring; ++dz) {
          if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != ring) continue;
          const std::int64_t x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
          if (x < 0 || y < 0 || z < 0 || x > kMaxCells + 2 || y > kMaxCells + 2 || z > kMaxCells + 2) continue;
          const std::uint32_t s = map_.find(detail::cell_key(x, y, z));
          if (s == detail::CellMap::kAbsent) continue;
          for (std::uint32_t m = begin_[s]; m < begin_[s + 1]; ++m) f(members_[m]);
        }
      }
    }
  }

  std::uint32_t cell_of(std::size_t i) const { return cell_of_[i]; }
  const std::uint32_t* members_begin(std::uint32_t s) const { return members_.data() + begin_[s]; }
  const std::uint32_t* members_end(std::uint32_t s) const { return members_.data() + begin_[s + 1]; }

 private:
  detail::CellMap map_;
  CellFrame frame_;
  bool valid_ = false;
  std::vector<std::uint32_t> cell_of_;
  std::vector<std::uint32_t> begin_;
  std::vector<std::uint32_t> members_;
};

// A cell about twice the cloud's spacing, its points spread over the bounding box's faces (a
// surface) or along its longest edge (a line), whichever is coarser: a few points per cell, and
// the nearest within the cell's own block.
double spacing_cell(const Bounds& b, std::size_t count) {
  const Eigen::Vector3d e = b.max - b.min;
  const double n = static_cast<double>(count);
  const double faces = 2.0 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
  return std::max({2.0 * std::sqrt(faces / n), 2.0 * e.maxCoeff() / n, e.maxCoeff() / kMaxCells * 2.0});
}

double brute_nearest_other(const PointList& points, std::size_t i) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < points.size(); ++j) {
    if (j != i) best = std::min(best, squared_distance(points[i], points[j]));
  }
  return best;
}

bool closer(double da, std::uint32_t ia, double db, std::uint32_t ib) { return da < db || (da == db && ia < ib); }

// Rings beyond the first block, at most this far: a point sparser is left to the kd-tree (a third
// ring, 343 cells, saved nothing on 100k-point solids).
constexpr std::int64_t kWidestRing = 2;

// Row i of all_nearest_neighbours from the cells within 2 (up to kWidestRing) rings of point i's,
// when at least k points lie within the reach of those rings: every point nearer lies in them, so
// the row is exact. False if no ring holds k (the kd-tree answers). `ranked`: scratch.
bool nearest_in_wider_rings(const Grid& grid, const PointList& points, std::uint32_t i, std::size_t k,
                            std::vector<std::pair<double, std::uint32_t>>& ranked, std::vector<std::uint32_t>& out) {
  const auto c = grid.coords(points[i]);
  ranked.clear();
  for (std::int64_t ring = 0; ring <= 1; ++ring) {
    grid.for_ring(c, ring, [&](std::uint32_t j) { ranked.emplace_back(squared_distance(points[i], points[j]), j); });
  }
  for (std::int64_t ring = 2; ring <= kWidestRing; ++ring) {
    grid.for_ring(c, ring, [&](std::uint32_t j) { ranked.emplace_back(squared_distance(points[i], points[j]), j); });
    const double reach = grid.reach(points[i], ring);
    const double limit = reach * reach;
    // Those within reach first (the k nearest are among them), then only the k nearest sorted.
    const auto inside = std::partition(ranked.begin(), ranked.end(), [&](const auto& r) { return r.first <= limit; });
    const auto within = static_cast<std::size_t>(inside - ranked.begin());
    if (within < k) continue;
    const auto by_distance = [](const auto& a, const auto& b) { return closer(a.first, a.second, b.first, b.second); };
    const auto kth = ranked.begin() + static_cast<std::ptrdiff_t>(k);
    std::nth_element(ranked.begin(), kth - 1, inside, by_distance);
    std::sort(ranked.begin(), kth, by_distance);
    for (std::size_t j = 0; j < k; ++j) out[i * k + j] = ranked[j].second;
    return true;
  }
  return false;
}

// The least squared distance from each query to another point of its 27-cell block (infinity if
// none): the cells of the queries' blocks numbered (by their bit's rank, or in a map), each with
// the queries it serves, then one pass over the points, each tested against the blocks, instead
// of binning them all. `extent`: the box of `frame`'s cells the points lie in (the bounds the
// caller passed), in cells.
std::vector<double> nearest_in_blocks(const PointList& points,
                                      const std::vector<std::uint32_t>& queries,
                                      const CellFrame& frame, const Eigen::Vector3d& extent,
                                      parallel::ThreadPool* pool) {
  // Every (block cell, query) pair, the cell by its packed key.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> pairs;
  pairs.reserve(queries.size() * 27);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const auto c = frame.coords(points[queries[q]]);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        for (std::int64_t dz = -1; dz <= 1; ++dz)
          pairs.emplace_back(detail::cell_key(c[0] + dx, c[1] + dy, c[2] + dz),
                             static_cast<std::uint32_t>(q));
      }
    }
  }
  // A bit per cell of that box (with the coordinates' margin), set where a block lies, and per
  // 64-bit word the bits set before it: a point tests its cell's bit (most lie in no block), and
  // a block cell's number is its bit's rank, with no hash map, whose lookups miss the cache. Where
  // the bits would take more than two bytes a point, or a block reaches beyond them (bounds that
  // are not the points' own), the cells go into the map instead.
  std::array<std::uint64_t, 3> dims{};
  double bits = 1.0;
  for (int a = 0; a < 3; ++a) {
    dims[a] = static_cast<std::uint64_t>(std::max(0.0, extent[a])) + 3;
    bits *= static_cast<double>(dims[a]);
  }
  const auto bit_of = [&dims](const std::array<std::int64_t, 3>& c) {
    return (static_cast<std::uint64_t>(c[0]) * dims[1] + static_cast<std::uint64_t>(c[1])) *
               dims[2] +
           static_cast<std::uint64_t>(c[2]);
  };
  const auto in_bits = [&dims](const std::array<std::int64_t, 3>& c) {
    return static_cast<std::uint64_t>(c[0]) < dims[0] &&
           static_cast<std::uint64_t>(c[1]) < dims[1] && static_cast<std::uint64_t>(c[2]) < dims[2];
  };
  bool by_rank = bits <= 16.0 * static_cast<double>(points.size());
  for (std::size_t p = 0; by_rank && p < pairs.size(); ++p)
    by_rank = in_bits(detail::cell_coords(pairs[p].first));
  std::vector<std::uint64_t> in_block;
  std::vector<std::uint32_t> word_rank;
  const auto rank_of = [&](std::uint64_t bit, std::uint64_t word) {
    return word_rank[bit >> 6] +
           static_cast<std::uint32_t>(
               std::bitset<64>(word & ((std::uint64_t{1} << (bit & 63)) - 1)).count());
  };
  detail::CellMap blocks(by_rank ? 16 : queries.size() * 27);
  std::vector<std::uint32_t> slot_of_pair(pairs.size());
  std::uint32_t block_cells = 0;
  if (by_rank) {
    in_block.assign((static_cast<std::size_t>(bits) + 63) / 64, 0);
    for (const auto& pair : pairs) {
      const std::uint64_t bit = bit_of(detail::cell_coords(pair.first));
      in_block[bit >> 6] |= std::uint64_t{1} << (bit & 63);
    }
    word_rank.assign(in_block.size() + 1, 0);
    for (std::size_t w = 0; w < in_block.size(); ++w)
      word_rank[w + 1] =
          word_rank[w] + static_cast<std::uint32_t>(std::bitset<64>(in_block[w]).count());
    block_cells = word_rank.back();
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const std::uint64_t bit = bit_of(detail::cell_coords(pairs[p].first));
      slot_of_pair[p] = rank_of(bit, in_block[bit >> 6]);
    }
  } else {
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      bool inserted = false;
      slot_of_pair[p] = blocks.find_or_insert(pairs[p].first, block_cells, inserted);
      block_cells += inserted ? 1 : 0;
    }
  }
  // The queries' points side by side: a hit reads them there, not across the whole cloud.
  std::vector<Point> query_point;
  query_point.reserve(queries.size());
  for (std::uint32_t q : queries) query_point.push_back(points[q]);
  std::vector<std::uint32_t> cell_begin(block_cells + 1, 0), cell_queries(pairs.size());
  for (const std::uint32_t b : slot_of_pair) ++cell_begin[b + 1];
  for (std::size_t b = 1; b < cell_begin.size(); ++b) cell_begin[b] += cell_begin[b - 1];
  std::vector<std::uint32_t> next(cell_begin.begin(), cell_begin.end() - 1);
  for (std::size_t p = 0; p < pairs.size(); ++p)
    cell_queries[next[slot_of_pair[p]]++] = pairs[p].second;
  // Blocks of points on the pool, each with its own minima; a minimum is the same in any order.
  constexpr std::size_t kPointsPerBlock = 16384;
  std::vector<std::vector<double>> best_of_block((points.size() + kPointsPerBlock - 1) / kPointsPerBlock);
  parallel::for_blocks(pool, points.size(), kPointsPerBlock, [&](std::size_t begin, std::size_t end) {
    std::vector<double>& best = best_of_block[begin / kPointsPerBlock];
    best.assign(queries.size(), std::numeric_limits<double>::infinity());
    for (std::size_t i = begin; i < end; ++i) {
      const auto c = frame.coords(points[i]);
      std::uint32_t slot = detail::CellMap::kAbsent;
      if (by_rank) {
        // Every block cell lies inside the bits: a point outside them is in none.
        if (!in_bits(c)) continue;
        const std::uint64_t bit = bit_of(c);
        const std::uint64_t word = in_block[bit >> 6];
        if (!((word >> (bit & 63)) & 1)) continue;
        slot = rank_of(bit, word);
      } else {
        slot = blocks.find(detail::cell_key(c[0], c[1], c[2]));
        if (slot == detail::CellMap::kAbsent) continue;
      }
      for (std::uint32_t e = cell_begin[slot]; e < cell_begin[slot + 1]; ++e) {
        const std::uint32_t q = cell_queries[e];
        if (queries[q] != i)
          best[q] = std::min(best[q], squared_distance(query_point[q], points[i]));
      }
    }
  });
  std::vector<double> best = std::move(best_of_block.front());
  for (std::size_t b = 1; b < best_of_block.size(); ++b) {
    for (std::size_t q = 0; q < queries.size(); ++q) best[q] = std::min(best[q], best_of_block[b][q]);
  }
  return best;
}

// Cells of the grid's array a point may cost at most (4 bytes each, with its member index: 20
// bytes a point); a sparser grid takes the map of nearest_in_blocks.
constexpr double kArrayCellsPerPoint = 4.0;

// nearest_in_blocks with every point binned in an array over the grid's cells (a counting sort):
// each query reads its own cell, then only those of the other 26 whose nearest side is nearer
// than the least distance found so far (less kSlack: no point there can be nearer, so the least
// is the same number). Nothing when the array would be too large, or a query's block reaches
// outside it (`extent`, in cells, is not that of the points' bounds).
std::optional<std::vector<double>> nearest_in_cell_array(const PointList& points,
                                                         const std::vector<std::uint32_t>& queries,
                                                         const CellFrame& frame, const Eigen::Vector3d& extent,
                                                         parallel::ThreadPool* pool) {
  std::array<std::int64_t, 3> dims{};
  double cells = 1.0;
  for (int a = 0; a < 3; ++a) {
    dims[a] = static_cast<std::int64_t>(extent[a]) + 3;
    cells *= static_cast<double>(dims[a]);
  }
  if (!(cells <= kArrayCellsPerPoint * static_cast<double>(points.size())) || !(cells < 4294967295.0)) return std::nullopt;
  const auto inside = [&](const std::array<std::int64_t, 3>& c, std::int64_t margin) {
    for (int a = 0; a < 3; ++a) {
      if (c[a] < margin || c[a] + margin >= dims[a]) return false;
    }
    return true;
  };
  const auto index = [&](const std::array<std::int64_t, 3>& c) {
    return static_cast<std::size_t>((c[0] * dims[1] + c[1]) * dims[2] + c[2]);
  };
  std::vector<std::uint32_t> cell_of(points.size());
  std::vector<std::uint32_t> begin(static_cast<std::size_t>(cells) + 1, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto c = frame.coords(points[i]);
    if (!inside(c, 0)) return std::nullopt;
    cell_of[i] = static_cast<std::uint32_t>(index(c));
    ++begin[cell_of[i] + 1];
  }
  for (std::size_t b = 1; b < begin.size(); ++b) begin[b] += begin[b - 1];
  std::vector<std::uint32_t> members(points.size());
  {
    std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) members[next[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  }
  for (std::uint32_t q : queries) {
    if (!inside(frame.coords(points[q]), 1)) return std::nullopt;
  }
  std::vector<double> best(queries.size(), std::numeric_limits<double>::infinity());
  const double cell = frame.cell;
  parallel::for_blocks(pool, queries.size(), 256, [&](std::size_t first, std::size_t last) {
    for (std::size_t q = first; q < last; ++q) {
      const std::uint32_t i = queries[q];
      const Point& p = points[i];
      const auto c = frame.coords(p);
      // The squared distance to the cell's lower side, none, and to its upper side along each
      // axis (less kSlack cells): by neighbour offset -1, 0, +1.
      const Eigen::Vector3d u = (p - frame.min) * frame.inv;
      std::array<std::array<double, 3>, 3> side{};
      for (int a = 0; a < 3; ++a) {
        const double below = u[a] - std::floor(u[a]);
        const double lo = std::max(0.0, below - kSlack) * cell, hi = std::max(0.0, 1.0 - below - kSlack) * cell;
        side[a] = {lo * lo, 0.0, hi * hi};
      }
      double least = std::numeric_limits<double>::infinity();
      const auto scan = [&](std::size_t at) {
        for (std::uint32_t m = begin[at]; m < begin[at + 1]; ++m) {
          const std::uint32_t j = members[m];
          if (j != i) least = std::min(least, squared_distance(p, points[j]));
        }
      };
      const std::size_t own = index(c);
      scan(own);
      const auto row = static_cast<std::size_t>(dims[2]), plane = static_cast<std::size_t>(dims[1] * dims[2]);
      for (std::size_t dx = 0; dx < 3; ++dx) {
        for (std::size_t dy = 0; dy < 3; ++dy) {
          const double gap_xy = side[0][dx] + side[1][dy];
          if (gap_xy > least) continue;
          for (std::size_t dz = 0; dz < 3; ++dz) {
            const std::size_t at = own + dx * plane + dy * row + dz - plane - row - 1;
            if (at == own || gap_xy + side[2][dz] > least) continue;
            scan(at);
          }
        }
      }
      best[q] = least;
    }
  });
  return best;
}

}  // namespace

std::vector<double> nearest_other_distances(const PointList& points, const std::vector<std::uint32_t>& queries,
                                            parallel::ThreadPool* pool, const Bounds* bounds) {
  std::vector<double> out(queries.size(), 0.0);
  if (points.size() < 2) return out;
  const Bounds box = bounds ? *bounds : bounding_box(points);
  const double cell = spacing_cell(box, points.size());
  const double inv = 1.0 / cell;
  const Eigen::Vector3d extent = (box.max - box.min) * inv;
  const bool valid = cell > 0.0 && std::isfinite(inv) && extent.allFinite() && extent.maxCoeff() < kMaxCells;
  std::vector<std::size_t> hard;
  // Settles each open query `open[k]` whose least distance `best[k]` in `frame`'s blocks lies
  // within the block's reach (nothing outside it is nearer); the others stay open.
  const auto settle = [&](const CellFrame& frame, const std::vector<double>& best,
                          std::vector<std::size_t>& open) {
    std::vector<std::size_t> still;
    for (std::size_t k = 0; k < open.size(); ++k) {
      const double reach = frame.reach(points[queries[open[k]]], 1);
      if (best[k] <= reach * reach) {
        out[open[k]] = std::sqrt(best[k]);
      } else {
        still.push_back(open[k]);
      }
    }
    open = std::move(still);
  };
  if (!valid) {
    for (std::size_t q = 0; q < queries.size(); ++q) hard.push_back(q);
  } else {
    const CellFrame frame{box.min, cell, inv};
    std::optional<std::vector<double>> in_array = nearest_in_cell_array(points, queries, frame, extent, pool);
    for (std::size_t q = 0; q < queries.size(); ++q) hard.push_back(q);
    settle(frame, in_array ? *in_array : nearest_in_blocks(points, queries, frame, extent, pool),
           hard);
    // Queries far from every point of their block (a sparse stretch, an outlier) once more in
    // cells kWiderCells times as wide: one pass testing each point against their blocks, where a
    // scan costs a distance a point for each of them; from two on the pass is the cheaper (on a
    // million points five such scans took most of the search's time).
    if (hard.size() >= 2) {
      const double wide = cell * kWiderCells;
      const CellFrame wider{box.min, wide, 1.0 / wide};
      std::vector<std::uint32_t> at;
      for (std::size_t q : hard) at.push_back(queries[q]);
      settle(wider, nearest_in_blocks(points, at, wider, extent / kWiderCells, pool), hard);
    }
  }
  // Far from everything (an outlier) or a degenerate grid: a scan for a few, else a kd-tree.
  // (A kd-tree costs a few hundred distances' worth per point to build: a scan is cheaper for few.)
  if (hard.size() <= 32) {
    for (std::size_t q : hard) out[q] = std::sqrt(brute_nearest_other(points, queries[q]));
  } else {
    const KdTree tree(points);
    std::vector<std::uint32_t> idx;
    std::vector<double> d2;
    for (std::size_t q : hard) {
      tree.knn(points[queries[q]], 2, idx, &d2);
      out[q] = d2.size() < 2 ? 0.0 : std::sqrt(d2[1]);
    }
  }
  return out;
}

void all_nearest_neighbours(const PointList& points, std::size_t k, double cell, std::vector<std::uint32_t>& out,
                            parallel::ThreadPool* pool) {
  const std::size_t n = points.size();
  k = std::min(k, n);
  out.assign(n * k, 0);
  if (k == 0) return;
  const Grid grid(points, bounding_box(points), cell);
  std::vector<std::uint32_t> hard;
  if (!grid.valid()) {
    hard.resize(n);
    for (std::size_t i = 0; i < n; ++i) hard[i] = static_cast<std::uint32_t>(i);
  } else {
    // Blocks of cells, each writing only its own points' rows; the points the grid cannot answer
    // are listed per block and joined in block order.
    constexpr std::size_t kCellsPerBlock = 64;
    const std::size_t cells = grid.cells();
    std::vector<std::vector<std::uint32_t>> hard_of_block((cells + kCellsPerBlock - 1) / kCellsPerBlock);
    parallel::for_blocks(pool, cells, kCellsPerBlock, [&](std::size_t cell_begin, std::size_t cell_end) {
      std::vector<std::uint32_t>& block_hard = hard_of_block[cell_begin / kCellsPerBlock];
      // One candidate list per cell (its 27-cell block), shared by every point of the cell, its
      // coordinates apart so that the distances to all of them vectorise.
      std::vector<std::uint32_t> candidates;
      std::vector<double> cx, cy, cz;
      std::vector<std::pair<double, std::uint32_t>> wide;
      std::vector<double> best_d(k);
      std::vector<std::uint32_t> best_i(k), best_slot(k), earlier_slots;
      for (std::size_t s = cell_begin; s < cell_end; ++s) {
        const std::uint32_t* first = grid.members_begin(static_cast<std::uint32_t>(s));
        candidates.clear();
        const auto c = grid.coords(points[*first]);
        for (std::int64_t ring = 0; ring <= 1; ++ring) {
          grid.for_ring(c, ring, [&](std::uint32_t j) { candidates.push_back(j); });
        }
        const std::size_t m = candidates.size();
        cx.resize(m);
        cy.resize(m);
        cz.resize(m);
        for (std::size_t j = 0; j < m; ++j) {
          cx[j] = points[candidates[j]].x();
          cy[j] = points[candidates[j]].y();
          cz[j] = points[candidates[j]].z();
        }
        // The k nearest of each earlier point of this cell the block answered, as slots of the
        // candidate list, nearest first.
        std::size_t answered = 0;
        earlier_slots.clear();
        for (const std::uint32_t* it = first; it != grid.members_end(static_cast<std::uint32_t>(s)); ++it) {
          const std::uint32_t i = *it;
          const double qx = points[i].x(), qy = points[i].y(), qz = points[i].z();
          // squared_distance's sum, term by term (in SSE2's IEEE lanes below too: the same bits).
          const auto distance_to = [&](std::size_t j) {
            const double dx = qx - cx[j], dy = qy - cy[j], dz = qz - cz[j];
            double d = dx * dx;
            d += dy * dy;
            d += dz * dz;
            return d;
          };
          // Only points within the block's reach can be among the k nearest, unless fewer than
          // k are: then wider rings or the kd-tree answer. The k nearest of an earlier point are
          // k candidates too: this point's k nearest are no farther than the farthest of them (a
          // bound from the same computed distances, so exact), which spares most of the ranking.
          const double reach = grid.reach(points[i], 1);
          double limit = reach * reach;
          // The earlier point nearest this one (its own slot is the first of its k) gives the bound.
          if (answered > 0) {
            std::size_t nearest = 0;
            double nearest_d = distance_to(earlier_slots[0]);
            for (std::size_t e = 1; e < answered; ++e) {
              const double d = distance_to(earlier_slots[e * k]);
              if (d < nearest_d) {
                nearest = e;
                nearest_d = d;
              }
            }
            double farthest = 0.0;
            for (std::size_t j = 0; j < k; ++j) farthest = std::max(farthest, distance_to(earlier_slots[nearest * k + j]));
            limit = std::min(limit, farthest);
          }
          std::size_t within = 0, count = 0;
          const auto rank = [&](std::size_t j, double d) {
            ++within;
            const std::uint32_t id = candidates[j];
            if (count == k && !closer(d, id, best_d[k - 1], best_i[k - 1])) return;
            std::size_t at = count < k ? count++ : k - 1;
            while (at > 0 && closer(d, id, best_d[at - 1], best_i[at - 1])) {
              best_d[at] = best_d[at - 1];
              best_i[at] = best_i[at - 1];
              best_slot[at] = best_slot[at - 1];
              --at;
            }
            best_d[at] = d;
            best_i[at] = id;
            best_slot[at] = static_cast<std::uint32_t>(j);
          };
          // The distances and the limit in one pass, two candidates at a time where SSE2 is: a
          // pair neither of which is within the limit (most) costs no branch of its own.
          std::size_t j = 0;
#if defined(__SSE2__)
          const __m128d vqx = _mm_set1_pd(qx), vqy = _mm_set1_pd(qy), vqz = _mm_set1_pd(qz), vlimit = _mm_set1_pd(limit);
          for (; j + 2 <= m; j += 2) {
            const __m128d dx = _mm_sub_pd(vqx, _mm_loadu_pd(cx.data() + j));
            const __m128d dy = _mm_sub_pd(vqy, _mm_loadu_pd(cy.data() + j));
            const __m128d dz = _mm_sub_pd(vqz, _mm_loadu_pd(cz.data() + j));
            const __m128d d = _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
            const int near = _mm_movemask_pd(_mm_cmple_pd(d, vlimit));
            if (near == 0) continue;
            alignas(16) double lane[2];
            _mm_store_pd(lane, d);
            if (near & 1) rank(j, lane[0]);
            if (near & 2) rank(j + 1, lane[1]);
          }
#endif
          for (; j < m; ++j) {
            const double d = distance_to(j);
            if (d <= limit) rank(j, d);
          }
          // Fewer than k within the limit happens only when the reach sets it (the bound has k).
          if (within < k) {
            if (!nearest_in_wider_rings(grid, points, i, k, wide, out)) block_hard.push_back(i);
            continue;
          }
          std::copy(best_i.begin(), best_i.end(), out.begin() + static_cast<std::ptrdiff_t>(i * k));
          earlier_slots.insert(earlier_slots.end(), best_slot.begin(), best_slot.end());
          ++answered;
        }
      }
    });
    for (const auto& block_hard : hard_of_block) hard.insert(hard.end(), block_hard.begin(), block_hard.end());
  }
  if (hard.empty()) return;
  // Sparse spots (a line of points, an outlier): the k-th neighbour lies beyond the block.
  const KdTree tree(points);
  parallel::for_blocks(pool, hard.size(), 256, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint32_t> idx;
    std::vector<double> d2;
    std::vector<std::uint32_t> tied;
    std::vector<std::pair<double, std::uint32_t>> ranked;
    for (std::size_t h = begin; h < end; ++h) {
      const std::uint32_t i = hard[h];
      // Every point as near as the k-th, so that a tie at the k-th goes by index too.
      tree.knn(points[i], k, idx, &d2);
      tied.clear();
      tree.radius(points[i], std::max(std::sqrt(d2.back()) * (1.0 + 1e-9), 1e-150), tied);
      if (tied.size() >= k) idx.swap(tied);
      ranked.clear();
      for (std::uint32_t j : idx) ranked.emplace_back(squared_distance(points[i], points[j]), j);
      std::sort(ranked.begin(), ranked.end());
      for (std::size_t j = 0; j < k; ++j) out[i * k + j] = ranked[j].second;
    }
  });
}

}  // namespace cloudshape::geometry
