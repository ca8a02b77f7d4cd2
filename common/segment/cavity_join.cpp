#include "segment/cavity_join.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
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
  PointList nodes;
  std::vector<std::uint32_t> node_id;
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (label[n] < 0) continue;
    nodes.push_back(g.nodes[n]);
    node_id.push_back(n);
  }
  std::unique_ptr<geometry::KdTree> tree;
  std::vector<std::int32_t> group(static_cast<std::size_t>(segments));
  std::iota(group.begin(), group.end(), 0);
  std::vector<std::uint32_t> near;
  std::vector<char> counted(g.size(), 0);
  std::vector<std::uint32_t> contacts(static_cast<std::size_t>(segments), 0);
  std::vector<std::uint32_t> touched;
  for (std::int32_t s = 0; s < segments; ++s) {
    std::int32_t cur = group[s];
    for (std::int32_t round = 0; round < segments; ++round) {
      const std::vector<std::uint32_t>& own = members[cur];
      if (static_cast<std::int64_t>(own.size()) < cfg.min_object_nodes ||
          concavity(g, own) < cfg.cavity_concavity) {
        break;
      }
      if (!tree) tree = std::make_unique<geometry::KdTree>(nodes);
      double spacing = 0.0;
      for (std::uint32_t n : own) spacing += g.spacing[n];
      spacing /= static_cast<double>(own.size());
      std::fill(contacts.begin(), contacts.end(), 0u);
      touched.clear();
      for (std::uint32_t n : own) {
        tree->radius(g.nodes[n], cfg.cavity_gap * spacing, near);
        for (std::uint32_t k : near) {
          const std::uint32_t m = node_id[k];
          if (group[label[m]] == cur || counted[m]) continue;
          counted[m] = 1;
          touched.push_back(m);
          ++contacts[group[label[m]]];
        }
      }
      for (std::uint32_t m : touched) counted[m] = 0;
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
