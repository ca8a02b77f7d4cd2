#include "segment/structure_planes_scoring.hpp"

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cloudshape::segment {

ScoredNodes::ScoredNodes(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes, double band) {
  for (auto* column : {&x, &y, &z, &nx, &ny, &nz, &limit}) column->reserve(nodes.size());
  for (std::uint32_t n : nodes) {
    x.push_back(g.nodes[n].x());
    y.push_back(g.nodes[n].y());
    z.push_back(g.nodes[n].z());
    nx.push_back(g.normals[n].x());
    ny.push_back(g.normals[n].y());
    nz.push_back(g.normals[n].z());
    limit.push_back(band * g.spacing[n]);
  }
}

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
  // In chunks of 64 nodes, each lane's count kept as minus the sum of its all-ones masks; between
  // chunks: could the rest still lift the count above must_beat?
  constexpr std::size_t kChunk = 64;
  for (; j + kChunk <= size; j += kChunk) {
    if (count + (size - j) <= must_beat) return count;
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
