#include "segment/cavity_join.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "geometry/kdtree.hpp"

namespace cloudshape::segment {

double concavity(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes) {
  if (nodes.size() < 3) return 0.0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::uint32_t n : nodes) c += g.nodes[n];
  c /= static_cast<double>(nodes.size());
  double facing = 0.0;
  double spread = 0.0;
  for (std::uint32_t n : nodes) {
    const Eigen::Vector3d d = g.nodes[n] - c;
    facing += g.normals[n].dot(d);
    spread += d.squaredNorm();
  }
  const double rms = std::sqrt(spread / static_cast<double>(nodes.size()));
  return rms > 0.0 ? -facing / static_cast<double>(nodes.size()) / rms : 0.0;
}

void join_cavities(const NeighbourGraph& g, std::vector<std::int32_t>& label, const config::SegmentConfig& cfg) {
  std::int32_t segments = 0;
  for (std::int32_t l : label) segments = std::max(segments, l + 1);
  if (segments < 2) return;
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(segments));
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (label[n] >= 0) members[label[n]].push_back(n);
  }
  // The container is the segment with the most nodes near the cavity: its rim is often cut from
  // the cavity by depth jumps (the far inner wall behind the near rim), so graph edges miss it.
  // A cavity joined to another piece of the inside (its floor) is still a cavity and looks again.
  // Near: within the gap of some node of the cavity, asked of a tree over the cavity's own nodes
  // for each node in its box widened by the gap (one query per node, not one radius search,
  // hundreds of nodes each, per cavity node).
  std::vector<std::int32_t> group(static_cast<std::size_t>(segments));
  std::iota(group.begin(), group.end(), 0);
  std::vector<std::uint32_t> contacts(static_cast<std::size_t>(segments), 0);
  PointList own_points;
  for (std::int32_t s = 0; s < segments; ++s) {
    std::int32_t cur = group[s];
    for (std::int32_t round = 0; round < segments; ++round) {
      const std::vector<std::uint32_t>& own = members[cur];
      if (static_cast<std::int64_t>(own.size()) < cfg.min_object_nodes ||
          concavity(g, own) < cfg.cavity_concavity) {
        break;
      }
      double spacing = 0.0;
      for (std::uint32_t n : own) spacing += g.spacing[n];
      spacing /= static_cast<double>(own.size());
      const double gap = cfg.cavity_gap * spacing;
      own_points.clear();
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
      for (std::uint32_t n : own) {
        own_points.push_back(g.nodes[n]);
        lo = lo.cwiseMin(g.nodes[n]);
        hi = hi.cwiseMax(g.nodes[n]);
      }
      // Widened a little more than the gap: the box only spares queries, the tree decides.
      const Eigen::Vector3d reach = Eigen::Vector3d::Constant(gap * (1.0 + 1e-6) + 1e-12);
      lo -= reach;
      hi += reach;
      const geometry::KdTree tree(own_points);
      std::fill(contacts.begin(), contacts.end(), 0u);
      for (std::uint32_t m = 0; m < g.size(); ++m) {
        if (label[m] < 0 || group[label[m]] == cur) continue;
        const Point& p = g.nodes[m];
        if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
        if (tree.any_within(p, gap)) ++contacts[group[label[m]]];
      }
      const auto best = std::max_element(contacts.begin(), contacts.end());
      if (*best == 0) break;
      const auto other = static_cast<std::int32_t>(best - contacts.begin());
      const std::int32_t keep = std::min(cur, other);
      const std::int32_t drop = std::max(cur, other);
      for (std::int32_t& gr : group) {
        if (gr == drop) gr = keep;
      }
      members[keep].insert(members[keep].end(), members[drop].begin(), members[drop].end());
      members[drop].clear();
      cur = keep;
    }
  }
  std::vector<std::int32_t> dense(static_cast<std::size_t>(segments), -1);
  std::int32_t next = 0;
  for (std::int32_t& l : label) {
    if (l < 0) continue;
    const std::int32_t r = group[l];
    if (dense[r] < 0) dense[r] = next++;
    l = dense[r];
  }
}

}  // namespace cloudshape::segment
