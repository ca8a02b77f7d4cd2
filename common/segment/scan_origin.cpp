#include "segment/scan_origin.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace cloudshape::segment {

std::optional<Point> scan_origin(const PointList& points, const config::SegmentConfig& cfg,
                                 parallel::ThreadPool* pool) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  constexpr std::size_t kMinPoints = 100;
  // A beam holds a ring's worth of returns; a sparse cloud leaves bins empty by chance alone.
  constexpr double kMinPerBeam = 10.0;
  // Fewer beams than the fewest a multi-beam lidar has: a plane through the origin fills one bin.
  constexpr std::size_t kMinBeams = 4;
  const double bin = cfg.scan_elevation_bin_degrees;
  if (!(bin > 0.0) || points.size() < kMinPoints) return std::nullopt;
  // Each block of points counts its own bins; the counts are summed after (integers: the same
  // sums for any blocks, so one block when no other thread would take one).
  const std::size_t per_block = pool != nullptr && pool->size() > 1 ? 16384 : points.size();
  const std::size_t blocks = (points.size() + per_block - 1) / per_block;
  std::vector<std::unordered_map<std::int64_t, std::size_t>> block_counts(blocks);
  std::vector<std::size_t> block_used(blocks, 0);
  parallel::for_blocks(pool, points.size(), per_block, [&](std::size_t begin, std::size_t end) {
    auto& counts = block_counts[begin / per_block];
    std::size_t& used = block_used[begin / per_block];
    for (std::size_t i = begin; i < end; ++i) {
      const Point& p = points[i];
      const double horizontal = std::hypot(p.x(), p.y());
      if (!p.allFinite() || (horizontal == 0.0 && p.z() == 0.0)) continue;
      const auto b = static_cast<std::int64_t>(std::floor(std::atan2(p.z(), horizontal) * kDegrees / bin));
      ++counts[b];
      ++used;
    }
  });
  std::unordered_map<std::int64_t, std::size_t> counts = std::move(block_counts.front());
  std::size_t used = block_used.front();
  for (std::size_t k = 1; k < blocks; ++k) {
    for (const auto& [b, c] : block_counts[k]) counts[b] += c;
    used += block_used[k];
  }
  if (used < kMinPoints) return std::nullopt;
  // A beam is a run of adjacent occupied bins with empty ones either side, holding a ring's worth
  // of points; a surface sampled any other way fills long runs (or, sparse, leaves a few points
  // in each of many short ones).
  std::vector<std::pair<std::int64_t, std::size_t>> bins(counts.begin(), counts.end());
  std::sort(bins.begin(), bins.end());
  std::size_t beams = 0, width = 0, in_beams = 0;
  for (std::size_t k = 0; k < bins.size();) {
    std::size_t end = k + 1, run = bins[k].second;
    while (end < bins.size() && bins[end].first == bins[end - 1].first + 1) run += bins[end++].second;
    if (static_cast<double>(run) >= kMinPerBeam) {
      ++beams;
      width += static_cast<std::size_t>(bins[end - 1].first - bins[k].first + 1);
      in_beams += run;
    }
    k = end;
  }
  if (beams < kMinBeams || static_cast<double>(width) > cfg.scan_beam_bins * static_cast<double>(beams) ||
      static_cast<double>(in_beams) < cfg.scan_beam_share * static_cast<double>(used)) {
    return std::nullopt;
  }
  return Point::Zero();
}

}  // namespace cloudshape::segment
