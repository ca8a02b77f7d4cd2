#include "segment/planar_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace cloudshape::segment {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::size_t kHypotheses = 16;
constexpr std::size_t kScored = 1024;

// The largest connected group of `candidates` over the graph's edges between them (`mark` holds
// `tag` on them while it looks, `tag + 1` after).
std::vector<std::uint32_t> largest_group(const NeighbourGraph& g,
                                         const std::vector<std::uint32_t>& candidates,
                                         std::vector<std::int32_t>& mark, std::int32_t tag) {
  for (std::uint32_t n : candidates) mark[n] = tag;
  std::vector<std::uint32_t> best, group, stack;
  for (std::uint32_t seed : candidates) {
    if (mark[seed] != tag) continue;
    group.clear();
    mark[seed] = tag + 1;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::uint32_t n = stack.back();
      stack.pop_back();
      group.push_back(n);
      g.for_neighbours(n, [&](std::uint32_t m) {
        if (mark[m] == tag) {
          mark[m] = tag + 1;
          stack.push_back(m);
        }
      });
    }
    if (group.size() > best.size()) best.swap(group);
  }
  return best;
}

}  // namespace

bool split_planar_pieces(const NeighbourGraph& g, std::vector<std::int32_t>& patch,
                         std::int32_t& patches, const config::SegmentConfig& cfg) {
  if (cfg.piece_max_planes < 2) return false;
  const double cos_smooth = std::cos(cfg.smooth_degrees * kPi / 180.0);
  const auto min_nodes = static_cast<std::size_t>(std::max<std::int64_t>(1, cfg.min_object_nodes));
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(patches));
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (patch[n] >= 0) members[patch[n]].push_back(n);
  }
  // Node n lies on the plane through node c with c's normal: within the band, its normal along.
  const auto on_plane = [&](std::uint32_t c, std::uint32_t n) {
    return std::abs(g.normals[c].dot(g.nodes[n] - g.nodes[c])) <= cfg.piece_band * g.spacing[c] &&
           g.normals[c].dot(g.normals[n]) >= cos_smooth;
  };
  std::vector<std::int32_t> mark(g.size(), 0);
  std::int32_t tag = 1;
  bool split = false;
  const std::int32_t original = patches;
  for (std::int32_t p = 0; p < original; ++p) {
    const std::vector<std::uint32_t>& all = members[p];
    if (all.size() < 2 * min_nodes) continue;
    std::vector<std::uint32_t> left = all;
    std::vector<std::vector<std::uint32_t>> pieces;
    std::vector<std::uint32_t> inliers;
    while (static_cast<std::int64_t>(pieces.size()) < cfg.piece_max_planes &&
           left.size() >= min_nodes) {
      // Hypotheses: the planes of nodes spread evenly through what is left, scored on at most
      // kScored of its nodes spread evenly too.
      const std::size_t stride = (left.size() + kScored - 1) / kScored;
      std::size_t best_count = 0;
      std::uint32_t best_node = left.front();
      for (std::size_t h = 0; h < kHypotheses; ++h) {
        const std::uint32_t c = left[(2 * h + 1) * left.size() / (2 * kHypotheses)];
        std::size_t count = 0;
        for (std::size_t k = 0; k < left.size(); k += stride) count += on_plane(c, left[k]) ? 1 : 0;
        if (count > best_count) {
          best_count = count;
          best_node = c;
        }
      }
      inliers.clear();
      for (std::uint32_t n : left) {
        if (on_plane(best_node, n)) inliers.push_back(n);
      }
      std::vector<std::uint32_t> piece = largest_group(g, inliers, mark, tag);
      tag += 2;
      if (piece.size() < min_nodes) break;
      std::sort(piece.begin(), piece.end());
      std::vector<std::uint32_t> rest;
      std::set_difference(left.begin(), left.end(), piece.begin(), piece.end(),
                          std::back_inserter(rest));
      left.swap(rest);
      pieces.push_back(std::move(piece));
    }
    if (pieces.size() < 2 || static_cast<double>(all.size() - left.size()) <
                                 cfg.piece_cover * static_cast<double>(all.size()))
      continue;
    split = true;
    for (std::uint32_t n : left) patch[n] = -1;
    for (std::size_t k = 1; k < pieces.size(); ++k) {
      for (std::uint32_t n : pieces[k]) patch[n] = patches;
      ++patches;
    }
  }
  return split;
}

}  // namespace cloudshape::segment
