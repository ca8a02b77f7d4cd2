#include "segment/structure_planes_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cloudshape::segment {

namespace {

// A node's cell on a 1024-cell grid per axis over the nodes' box, bits interleaved (Morton
// order): nodes in one chunk of the sorted order lie close together.
std::uint32_t morton_key(const Point& p, const Point& lo, const Eigen::Vector3d& scale) {
  std::uint32_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double q = (p(axis) - lo(axis)) * scale(axis);
    std::uint32_t cell = static_cast<std::uint32_t>(q >= 0.0 && q < 1023.0 ? q : q >= 1023.0 ? 1023.0 : 0.0);
    // The ten bits spread to every third bit.
    cell = (cell | (cell << 16)) & 0x030000ffu;
    cell = (cell | (cell << 8)) & 0x0300f00fu;
    cell = (cell | (cell << 4)) & 0x030c30c3u;
    cell = (cell | (cell << 2)) & 0x09249249u;
    key |= cell << axis;
  }
  return key;
}

}  // namespace

ScoredNodes::ScoredNodes(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes, double band) {
  Point lo = Point::Constant(std::numeric_limits<double>::infinity());
  Point hi = -lo;
  for (std::uint32_t n : nodes) {
    lo = lo.cwiseMin(g.nodes[n]);
    hi = hi.cwiseMax(g.nodes[n]);
  }
  Eigen::Vector3d scale;
  for (int axis = 0; axis < 3; ++axis) scale(axis) = hi(axis) > lo(axis) ? 1024.0 / (hi(axis) - lo(axis)) : 0.0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> order;  // (key, node): ties by node, deterministic
  order.reserve(nodes.size());
  for (std::uint32_t n : nodes) order.emplace_back(morton_key(g.nodes[n], lo, scale), n);
  std::sort(order.begin(), order.end());
  for (auto* column : {&x, &y, &z, &nx, &ny, &nz, &limit}) column->reserve(nodes.size());
  for (const auto& [key, n] : order) {
    x.push_back(g.nodes[n].x());
    y.push_back(g.nodes[n].y());
    z.push_back(g.nodes[n].z());
    nx.push_back(g.normals[n].x());
    ny.push_back(g.normals[n].y());
    nz.push_back(g.normals[n].z());
    limit.push_back(band * g.spacing[n]);
  }
  for (std::size_t j = 0; j + kChunk <= size(); j += kChunk) {
    const auto box = [&](const std::vector<double>& v, std::vector<double>& centre, std::vector<double>& half) {
      const auto [min, max] = std::minmax_element(v.begin() + j, v.begin() + j + kChunk);
      centre.push_back(0.5 * (*min + *max));
      half.push_back(0.5 * (*max - *min));
    };
    box(x, centre_x, half_x);
    box(y, centre_y, half_y);
    box(z, centre_z, half_z);
    chunk_limit.push_back(*std::max_element(limit.begin() + j, limit.begin() + j + kChunk));
  }
}

namespace {

// Whether every node of chunk `k` lies farther from the plane than the chunk's largest limit, as
// the count computes distances: the box's nearest point is beyond the limit by more than any
// rounding of a distance (a relative 1e-9 of the terms' magnitudes, far above a few ulps), so
// the chunk adds nothing and is skipped whole. NaN anywhere: not skipped.
bool chunk_beyond_band(const ScoredNodes& nodes, std::size_t k, double a, double b, double c, double offset) {
  const double centre = a * nodes.centre_x[k] + b * nodes.centre_y[k] + c * nodes.centre_z[k] + offset;
  const double reach = std::abs(a) * nodes.half_x[k] + std::abs(b) * nodes.half_y[k] + std::abs(c) * nodes.half_z[k];
  const double magnitude = std::abs(a * nodes.centre_x[k]) + std::abs(b * nodes.centre_y[k]) +
                           std::abs(c * nodes.centre_z[k]) + std::abs(offset) + reach;
  return std::abs(centre) - reach > nodes.chunk_limit[k] + 1e-9 * magnitude;
}

}  // namespace

std::size_t count_plane_inliers(const ScoredNodes& nodes, const geometry::Plane& p, double min_cos,
                                std::size_t must_beat) {
  const double a = p.normal.x(), b = p.normal.y(), c = p.normal.z(), offset = p.offset;
  const double* x = nodes.x.data();
  const double* y = nodes.y.data();
  const double* z = nodes.z.data();
  const double* nx = nodes.nx.data();
  const double* ny = nodes.ny.data();
  const double* nz = nodes.nz.data();
  const double* limit = nodes.limit.data();
  // Eigen sums a 3-vector's dot product left to right: the same sums here, so the same
  // distances and cosines to the bit (StructureScoring.CountsAsIsInlierDoes checks it). Two
  // nodes at a time where SSE2 is (IEEE double lanes: the same results as the scalar code).
  std::size_t count = 0;
  std::size_t j = 0;
#if defined(__SSE2__)
  const __m128d va = _mm_set1_pd(a), vb = _mm_set1_pd(b), vc = _mm_set1_pd(c), voffset = _mm_set1_pd(offset);
  const __m128d vmin_cos = _mm_set1_pd(min_cos);
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  const std::size_t size = nodes.size();
  // In chunks of kChunk nodes, each lane's count kept as minus the sum of its all-ones masks; between
  // chunks: could the rest still lift the count above must_beat?
  constexpr std::size_t kChunk = ScoredNodes::kChunk;
  for (; j + kChunk <= size; j += kChunk) {
    if (count + (size - j) <= must_beat) return count;
    if (chunk_beyond_band(nodes, j / kChunk, a, b, c, offset)) continue;
    __m128i lanes = _mm_setzero_si128();
    for (std::size_t q = j; q < j + kChunk; q += 2) {
      const __m128d distance = _mm_add_pd(
          _mm_add_pd(_mm_add_pd(_mm_mul_pd(va, _mm_loadu_pd(x + q)), _mm_mul_pd(vb, _mm_loadu_pd(y + q))),
                     _mm_mul_pd(vc, _mm_loadu_pd(z + q))),
          voffset);
      const __m128d cosine = _mm_add_pd(
          _mm_add_pd(_mm_mul_pd(_mm_loadu_pd(nx + q), va), _mm_mul_pd(_mm_loadu_pd(ny + q), vb)),
          _mm_mul_pd(_mm_loadu_pd(nz + q), vc));
      const __m128d near = _mm_cmple_pd(_mm_and_pd(distance, magnitude), _mm_loadu_pd(limit + q));
      const __m128d aligned = _mm_cmpge_pd(_mm_and_pd(cosine, magnitude), vmin_cos);
      lanes = _mm_sub_epi64(lanes, _mm_castpd_si128(_mm_and_pd(near, aligned)));
    }
    alignas(16) std::int64_t lane[2];
    _mm_store_si128(reinterpret_cast<__m128i*>(lane), lanes);
    count += static_cast<std::size_t>(lane[0] + lane[1]);
  }
#endif
  for (; j < nodes.size(); ++j) {
    const double distance = a * x[j] + b * y[j] + c * z[j] + offset;
    const double cosine = nx[j] * a + ny[j] * b + nz[j] * c;
    count += static_cast<std::size_t>((std::abs(distance) <= limit[j]) & (std::abs(cosine) >= min_cos));
  }
  return count;
}

}  // namespace cloudshape::segment
