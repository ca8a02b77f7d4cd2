#include "segment/scan_origin.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "segment/scan_beams.hpp"

namespace cloudshape::segment {

std::optional<Point> scan_origin(const PointList& points, const config::SegmentConfig& cfg,
                                 parallel::ThreadPool* pool) {
  constexpr std::size_t kMinPoints = 100;
  // Fewer beams than the fewest a multi-beam lidar has: a plane through the origin fills one bin.
  constexpr std::size_t kMinBeams = 4;
  const double bin = cfg.scan_elevation_bin_degrees;
  if (!(bin > 0.0) || points.size() < kMinPoints) return std::nullopt;
  const ElevationBins bins(bin);
  // Each block of points counts its own bins (an array over the tabulated bins, else a map); the
  // counts are summed after (integers: the same sums for any blocks, so one block when no other
  // thread would take one).
  const std::size_t per_block = pool != nullptr && pool->size() > 1 ? 16384 : points.size();
  const std::size_t blocks = (points.size() + per_block - 1) / per_block;
  std::vector<std::vector<std::size_t>> block_dense(blocks);
  std::vector<std::unordered_map<std::int64_t, std::size_t>> block_counts(blocks);
  std::vector<std::size_t> block_used(blocks, 0);
  parallel::for_blocks(pool, points.size(), per_block, [&](std::size_t begin, std::size_t end) {
    auto& dense = block_dense[begin / per_block];
    auto& counts = block_counts[begin / per_block];
    std::size_t& used = block_used[begin / per_block];
    if (!bins.tabulated()) {
      for (std::size_t i = begin; i < end; ++i) {
        const std::optional<std::int64_t> b = bins(points[i]);
        if (!b) continue;
        ++counts[*b];
        ++used;
      }
      return;
    }
    dense.assign(bins.span(), 0);
    used = bins.count_bins(points.data() + begin, points.data() + end, dense.data());
  });
  std::size_t used = 0;
  for (std::size_t u : block_used) used += u;
  if (used < kMinPoints) return std::nullopt;
  // Beams (runs of adjacent occupied bins holding a ring's worth of points); a surface sampled
  // any other way fills long runs (or, sparse, leaves a few points in each of many short ones).
  std::vector<std::pair<std::int64_t, std::size_t>> sorted;
  if (bins.tabulated()) {
    for (std::size_t b = 0; b < bins.span(); ++b) {
      std::size_t count = 0;
      for (const auto& dense : block_dense) count += dense[b];
      if (count > 0) sorted.emplace_back(bins.lowest() + static_cast<std::int64_t>(b), count);
    }
  } else {
    std::unordered_map<std::int64_t, std::size_t> counts = std::move(block_counts.front());
    for (std::size_t k = 1; k < blocks; ++k) {
      for (const auto& [b, c] : block_counts[k]) counts[b] += c;
    }
    sorted.assign(counts.begin(), counts.end());
    std::sort(sorted.begin(), sorted.end());
  }
  const std::vector<ElevationBeam> found = elevation_beams(sorted);
  const std::size_t beams = found.size();
  std::size_t width = 0, in_beams = 0;
  for (const ElevationBeam& b : found) {
    width += static_cast<std::size_t>(b.last_bin - b.first_bin + 1);
    in_beams += b.points;
  }
  if (beams < kMinBeams || static_cast<double>(width) > cfg.scan_beam_bins * static_cast<double>(beams) ||
      static_cast<double>(in_beams) < cfg.scan_beam_share * static_cast<double>(used)) {
    return std::nullopt;
  }
  return Point::Zero();
}

}  // namespace cloudshape::segment
