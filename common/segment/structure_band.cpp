#include "segment/structure_band.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cloudshape::segment {
namespace {

#if defined(__SSE2__)
// Two packed 3-vectors (x, y, z doubles) as lanes (x0, x1), (y0, y1), (z0, z1).
struct Lanes {
  __m128d x, y, z;
};

Lanes load_lanes(const double* v0, const double* v1) {
  const __m128d xy0 = _mm_loadu_pd(v0), xy1 = _mm_loadu_pd(v1);
  return {_mm_unpacklo_pd(xy0, xy1), _mm_unpackhi_pd(xy0, xy1),
          _mm_loadh_pd(_mm_load_sd(v0 + 2), v1 + 2)};
}

// Eigen sums a 3-vector's dot product left to right: the same sums here, in IEEE double lanes,
// so the same signed distances to the bit as p.signed_distance.
__m128d signed_distance(const Lanes& v, __m128d a, __m128d b, __m128d c, __m128d offset) {
  return _mm_add_pd(
      _mm_add_pd(_mm_add_pd(_mm_mul_pd(a, v.x), _mm_mul_pd(b, v.y)), _mm_mul_pd(c, v.z)), offset);
}

static_assert(sizeof(Point) == 3 * sizeof(double), "nodes and normals are packed x, y, z");
#endif

// Kept nodes go to a block on the stack: every node written, the block's end moved past the kept
// ones (no branch per node), the block appended to the list after each kBlock nodes. A list as
// long as all nodes, zeroed first, would cost more than the nodes' test.
constexpr std::size_t kBlock = 256;
using Block = std::array<std::uint32_t, kBlock>;

#if defined(__SSE2__)
// Writes nodes n0 and n1 at block[end] and on, moving `end` past those whose bit is set in
// `lanes` (bit 0: n0, bit 1: n1).
void keep_two(Block& block, std::size_t& end, std::uint32_t n0, std::uint32_t n1, int lanes) {
  block[end] = n0;
  end += static_cast<std::size_t>(lanes & 1);
  block[end] = n1;
  end += static_cast<std::size_t>(lanes >> 1);
}
#endif

}  // namespace

std::vector<std::uint32_t> band_nodes(const NeighbourGraph& g,
                                      const std::vector<std::uint32_t>& nodes,
                                      const geometry::Plane& p, double band, double min_cos) {
  std::vector<std::uint32_t> out;
  out.reserve(nodes.size());
  Block kept;
#if defined(__SSE2__)
  // The cosine summed as Eigen sums normal.dot(p.normal), too: the same bits as is_inlier's test
  // (StructureBand.SameNodesInTheSameOrderAsIsInlier).
  const double* position = g.nodes.empty() ? nullptr : g.nodes.front().data();
  const double* normal = g.normals.empty() ? nullptr : g.normals.front().data();
  const double* spacing = g.spacing.data();
  const __m128d a = _mm_set1_pd(p.normal.x()), b = _mm_set1_pd(p.normal.y()),
                c = _mm_set1_pd(p.normal.z());
  const __m128d offset = _mm_set1_pd(p.offset), vband = _mm_set1_pd(band),
                vmin_cos = _mm_set1_pd(min_cos);
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
#endif
  for (std::size_t begin = 0; begin < nodes.size(); begin += kBlock) {
    const std::size_t end = std::min(nodes.size(), begin + kBlock);
    std::size_t count = 0, i = begin;
#if defined(__SSE2__)
    for (; i + 2 <= end; i += 2) {
      const std::uint32_t n0 = nodes[i], n1 = nodes[i + 1];
      const std::size_t at0 = 3 * static_cast<std::size_t>(n0),
                        at1 = 3 * static_cast<std::size_t>(n1);
      const __m128d distance =
          signed_distance(load_lanes(position + at0, position + at1), a, b, c, offset);
      const Lanes n = load_lanes(normal + at0, normal + at1);
      const __m128d cosine =
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(n.x, a), _mm_mul_pd(n.y, b)), _mm_mul_pd(n.z, c));
      const __m128d limit =
          _mm_mul_pd(vband, _mm_loadh_pd(_mm_load_sd(spacing + n0), spacing + n1));
      const int accepted =
          _mm_movemask_pd(_mm_and_pd(_mm_cmple_pd(_mm_and_pd(distance, magnitude), limit),
                                     _mm_cmpge_pd(_mm_and_pd(cosine, magnitude), vmin_cos)));
      keep_two(kept, count, n0, n1, accepted);
    }
#endif
    for (; i < end; ++i) {
      const std::uint32_t n = nodes[i];
      kept[count] = n;
      count += std::abs(p.signed_distance(g.nodes[n])) <= band * g.spacing[n] &&
                       std::abs(g.normals[n].dot(p.normal)) >= min_cos
                   ? 1
                   : 0;
    }
    out.insert(out.end(), kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(count));
  }
  return out;
}

void nodes_above(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes,
                 const std::vector<char>& skip, const geometry::Plane& p, double low, double high,
                 double lift, std::vector<std::uint32_t>& above, std::vector<std::uint32_t>& near) {
  const bool lifted = lift > 0.0;
  above.reserve(nodes.size());
  Block up, close;
#if defined(__SSE2__)
  const double* position = g.nodes.empty() ? nullptr : g.nodes.front().data();
  const double* spacing = g.spacing.data();
  const __m128d a = _mm_set1_pd(p.normal.x()), b = _mm_set1_pd(p.normal.y()),
                c = _mm_set1_pd(p.normal.z());
  const __m128d offset = _mm_set1_pd(p.offset), vlow = _mm_set1_pd(low), vhigh = _mm_set1_pd(high),
                vlift = _mm_set1_pd(lift);
  const __m128d zero = _mm_setzero_pd();
#endif
  for (std::size_t begin = 0; begin < nodes.size(); begin += kBlock) {
    const std::size_t end = std::min(nodes.size(), begin + kBlock);
    std::size_t up_end = 0, close_end = 0, i = begin;
#if defined(__SSE2__)
    for (; i + 2 <= end; i += 2) {
      const std::uint32_t n0 = nodes[i], n1 = nodes[i + 1];
      const Lanes x = load_lanes(position + 3 * static_cast<std::size_t>(n0),
                                 position + 3 * static_cast<std::size_t>(n1));
      const __m128d distance = signed_distance(x, a, b, c, offset);
      const __m128d height =
          _mm_div_pd(distance, _mm_loadh_pd(_mm_load_sd(spacing + n0), spacing + n1));
      const int skipped = (skip[n0] != 0) | (skip[n1] != 0) << 1;
      const int lifted_bits = lifted ? _mm_movemask_pd(_mm_cmpnle_pd(distance, vlift)) : 3;
      const int up_bits = _mm_movemask_pd(_mm_cmpnle_pd(height, zero)) & lifted_bits & ~skipped;
      const int close_bits =
          _mm_movemask_pd(_mm_and_pd(_mm_cmpgt_pd(height, vlow), _mm_cmple_pd(height, vhigh))) &
          ~skipped;
      keep_two(up, up_end, n0, n1, up_bits);
      keep_two(close, close_end, n0, n1, close_bits);
    }
#endif
    for (; i < end; ++i) {
      const std::uint32_t n = nodes[i];
      const double distance = p.signed_distance(g.nodes[n]);
      const double height = distance / g.spacing[n];
      const bool is_up = !skip[n] && !(height <= 0.0) && (!lifted || !(distance <= lift));
      up[up_end] = n;
      up_end += is_up ? 1 : 0;
      close[close_end] = n;
      close_end += !skip[n] && height > low && height <= high ? 1 : 0;
    }
    above.insert(above.end(), up.begin(), up.begin() + static_cast<std::ptrdiff_t>(up_end));
    near.insert(near.end(), close.begin(), close.begin() + static_cast<std::ptrdiff_t>(close_end));
  }
}

#if defined(__SSE2__)
namespace {

// The nodes first .. first + 15 whose bit is set in `bits`, written at `out`; how many.
std::size_t write_set(std::uint32_t* out, std::uint32_t first, unsigned bits) {
  if (bits == 0xffffu) {
    __m128i n = _mm_add_epi32(_mm_set1_epi32(static_cast<int>(first)), _mm_setr_epi32(0, 1, 2, 3));
    for (int k = 0; k < 4; ++k, n = _mm_add_epi32(n, _mm_set1_epi32(4))) {
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 4 * k), n);
    }
    return 16;
  }
  std::size_t count = 0;
  for (; bits != 0; bits &= bits - 1)
    out[count++] = first + static_cast<std::uint32_t>(__builtin_ctz(bits));
  return count;
}

}  // namespace
#endif

void split_nodes(const NeighbourGraph& g, const std::vector<char>& removed,
                 const std::vector<char>& tried, double max_curvature,
                 std::vector<std::uint32_t>& active, std::vector<std::uint32_t>& searched,
                 std::vector<std::uint32_t>& seeds) {
  for (auto* list : {&active, &searched, &seeds}) list->reserve(g.size());
  Block a, s, f;
  const std::size_t size = g.size();
  for (std::size_t begin = 0; begin < size; begin += kBlock) {
    const std::size_t end = std::min(size, begin + kBlock);
    std::size_t a_end = 0, s_end = 0, f_end = 0, n = begin;
#if defined(__SSE2__)
    // Sixteen nodes' flags at a time as bit masks, the kept nodes read off the set bits: a
    // searched region's nodes are mostly all kept, a removed one's all dropped.
    const __m128i zero = _mm_setzero_si128();
    const __m128d flat = _mm_set1_pd(max_curvature);
    for (; n + 16 <= end; n += 16) {
      const auto flags = [&](const std::vector<char>& v) {
        return static_cast<unsigned>(_mm_movemask_epi8(
            _mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(v.data() + n)), zero)));
      };
      const unsigned keep = flags(removed);
      const unsigned search = keep & flags(tried);
      unsigned seed = 0;
      if (search != 0) {
        for (int k = 0; k < 16; k += 2) {
          seed |= static_cast<unsigned>(
                      _mm_movemask_pd(_mm_cmplt_pd(_mm_loadu_pd(g.curvature.data() + n + k), flat)))
                  << k;
        }
      }
      const auto first = static_cast<std::uint32_t>(n);
      a_end += write_set(a.data() + a_end, first, keep);
      s_end += write_set(s.data() + s_end, first, search);
      f_end += write_set(f.data() + f_end, first, search & seed);
    }
#endif
    for (; n < end; ++n) {
      const bool keep = !removed[n];
      const bool search = keep && !tried[n];
      const auto node = static_cast<std::uint32_t>(n);
      a[a_end] = node;
      a_end += keep ? 1 : 0;
      s[s_end] = node;
      s_end += search ? 1 : 0;
      f[f_end] = node;
      f_end += search && g.curvature[n] < max_curvature ? 1 : 0;
    }
    active.insert(active.end(), a.begin(), a.begin() + static_cast<std::ptrdiff_t>(a_end));
    searched.insert(searched.end(), s.begin(), s.begin() + static_cast<std::ptrdiff_t>(s_end));
    seeds.insert(seeds.end(), f.begin(), f.begin() + static_cast<std::ptrdiff_t>(f_end));
  }
}

std::vector<std::uint32_t> largest_connected(const NeighbourGraph& g,
                                             const std::vector<std::uint32_t>& members) {
  // Each member is visited once: every part's visit order goes into one array, one part after
  // the other, and the stack never holds more than all members. Neither is zeroed first.
  std::vector<char> unvisited(g.size(), 0);
  for (std::uint32_t n : members) unvisited[n] = 1;
  const std::unique_ptr<std::uint32_t[]> order(new std::uint32_t[members.size()]);
  const std::unique_ptr<std::uint32_t[]> stack(new std::uint32_t[members.size()]);
  std::size_t visited = 0, best_begin = 0, best_size = 0;
  // The edges through local pointers: a store to `unvisited` could otherwise be the graph's own
  // ends, read again for every edge.
  const std::uint32_t* const adjacency = g.adjacency.data();
  const std::uint32_t* const adjacency_begin = g.adjacency_begin.data();
  for (std::uint32_t seed : members) {
    if (!unvisited[seed]) continue;
    const std::size_t begin = visited;
    std::size_t depth = 1;
    stack[0] = seed;
    unvisited[seed] = 0;
    while (depth > 0) {
      const std::uint32_t n = stack[--depth];
      order[visited++] = n;
      const std::uint32_t* const last = adjacency + adjacency_begin[n + 1];
      for (const std::uint32_t* e = adjacency + adjacency_begin[n]; e != last; ++e) {
        const std::uint32_t m = *e;
        if (unvisited[m]) {
          unvisited[m] = 0;
          stack[depth++] = m;
        }
      }
    }
    if (visited - begin > best_size) {
      best_begin = begin;
      best_size = visited - begin;
    }
  }
  return std::vector<std::uint32_t>(order.get() + best_begin, order.get() + best_begin + best_size);
}

}  // namespace cloudshape::segment
