#include "segment/concave_cuts.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/pca.hpp"

namespace cloudshape::segment {
namespace {

struct Plane {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double band = 0.0;    // cfg.concave_cut_band of the nodes' spacings
  double spread = 0.0;  // the nodes' RMS distance from it
};

// The plane of `nodes`, when they lie flat within the band (three standard deviations).
std::optional<Plane> flat_plane(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes, std::size_t min_nodes,
                                const config::SegmentConfig& cfg) {
  if (nodes.size() < std::max<std::size_t>(3, min_nodes)) return std::nullopt;
  double spacing = 0.0;
  for (std::uint32_t n : nodes) spacing += g.spacing[n];
  spacing /= static_cast<double>(nodes.size());
  const geometry::Pca pca = geometry::compute_pca(g.nodes, nodes);
  Plane plane{pca.centroid, pca.eigenvectors.col(0).normalized(), cfg.concave_cut_band * spacing,
              std::sqrt(std::max(0.0, pca.eigenvalues(0)))};
  if (!(plane.band > 0.0) || 3.0 * plane.spread > plane.band) return std::nullopt;
  return plane;
}

// Whether a flat patch lying across a cut is two faces meeting at a kink there, not one face: it
// spreads off its plane cfg.concave_cut_kink_ratio times as far as its pieces either side of the
// cut spread off theirs (one face's pieces spread as far as it does: its noise). The floor, a
// thousandth of the band, keeps noise-free pieces from dividing by their rounding.
bool kinked(const Plane& whole, const Plane& up, std::size_t up_nodes, const Plane& down,
            std::size_t down_nodes, const config::SegmentConfig& cfg) {
  if (!(cfg.concave_cut_kink_ratio > 0.0)) return false;
  const double u = static_cast<double>(up_nodes), d = static_cast<double>(down_nodes);
  const double pieces =
      std::sqrt((u * up.spread * up.spread + d * down.spread * down.spread) / (u + d));
  return whole.spread > cfg.concave_cut_kink_ratio * std::max(pieces, 1e-3 * whole.band);
}

// A cut: the patches going to the positive side whole, and those split by it.
struct Cut {
  std::vector<std::uint32_t> positive, split;
};

}  // namespace

std::vector<std::uint32_t> cut_at_concave_faces(const NeighbourGraph& g, std::vector<std::int32_t>& patch,
                                                const std::vector<char>& surface, std::int32_t& patches,
                                                std::vector<std::uint32_t> group, JunctionPairs pairs,
                                                const std::function<JunctionPairs(const std::vector<std::int32_t>&)>& rejudge,
                                                const config::SegmentConfig& cfg) {
  if (pairs.concave.empty() || !(cfg.concave_cut_band > 0.0)) return group;
  const auto min_nodes = static_cast<std::size_t>(std::max<std::int64_t>(1, cfg.min_object_nodes));
  std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(patches));  // surface nodes
  std::vector<std::vector<std::uint32_t>> all(static_cast<std::size_t>(patches));      // every node
  for (std::uint32_t n = 0; n < g.size(); ++n) {
    if (patch[n] < 0) continue;
    all[patch[n]].push_back(n);
    if (surface[n]) members[patch[n]].push_back(n);
  }
  std::uint32_t next_group = 0;
  for (std::uint32_t v : group) next_group = std::max(next_group, v + 1);
  const auto signed_distance = [&](const Plane& p, const Eigen::Vector3d& normal, std::uint32_t n) {
    return normal.dot(g.nodes[n] - p.centroid);
  };

  // The cut along `face` (the plane of patch `at`) with `other` on its positive side, or nothing
  // when a flat patch runs through it, a patch through it is not two flat pieces, a convex edge at
  // least as long as the concave junction (`concave_length`) runs along it, or a side is too small
  // to be an object.
  const auto cut_along = [&](std::uint32_t at, std::uint32_t other, std::uint32_t concave_length,
                             const Plane& face, Eigen::Vector3d& normal,
                             const std::vector<std::uint32_t>& in_segment) -> std::optional<Cut> {
    normal = face.normal;
    if (members[other].empty()) return std::nullopt;
    double mean_other = 0.0;
    for (std::uint32_t n : members[other]) mean_other += signed_distance(face, normal, n);
    mean_other /= static_cast<double>(members[other].size());
    if (std::abs(mean_other) <= face.band) return std::nullopt;
    if (mean_other < 0.0) normal = -normal;
    Cut cut;
    std::size_t nodes_positive = 0, nodes_negative = 0;
    for (std::uint32_t q : in_segment) {
      std::size_t above = 0, below = 0;
      if (q != at) {
        for (std::uint32_t n : members[q]) {
          const double d = signed_distance(face, normal, n);
          above += d > face.band;
          below += d < -face.band;
        }
      }
      const double cross = std::max(2.0, cfg.concave_cut_cross_share * static_cast<double>(members[q].size()));
      if (static_cast<double>(above) > cross && static_cast<double>(below) > cross) {
        // A face of one solid runs through the plane; a patch grown over two solids' parallel
        // faces (round a step finer than its smoothness), or over two faces meeting at a kink
        // (a box turned on a larger one: the fronts, where the lower top's strip runs out), is two
        // flat pieces, one either side.
        std::vector<std::uint32_t> up, down;
        for (std::uint32_t n : members[q])
          (signed_distance(face, normal, n) > face.band ? up : down).push_back(n);
        const std::optional<Plane> up_plane = flat_plane(g, up, 0, cfg),
                                   down_plane = flat_plane(g, down, 0, cfg);
        if (!up_plane || !down_plane) return std::nullopt;
        const std::optional<Plane> whole_plane = flat_plane(g, members[q], 0, cfg);
        if (whole_plane &&
            !kinked(*whole_plane, *up_plane, up.size(), *down_plane, down.size(), cfg))
          return std::nullopt;
        cut.split.push_back(q);
        for (std::uint32_t n : all[q])
          (signed_distance(face, normal, n) > face.band ? nodes_positive : nodes_negative) += 1;
      } else if (static_cast<double>(above) > cross) {
        cut.positive.push_back(q);
        nodes_positive += all[q].size();
      } else {
        nodes_negative += all[q].size();
      }
    }
    if (nodes_positive < min_nodes || nodes_negative < min_nodes) return std::nullopt;
    const auto positive = [&](std::uint32_t q) {
      return std::find(cut.positive.begin(), cut.positive.end(), q) != cut.positive.end();
    };
    if (!positive(other)) return std::nullopt;
    // Split patches have a piece on both sides: their junctions say nothing of the cut; nor do
    // an edge band's slivers.
    const auto whole = [&](std::uint32_t q) {
      return group[q] == group[at] && members[q].size() >= min_nodes &&
             std::find(cut.split.begin(), cut.split.end(), q) == cut.split.end();
    };
    for (const PatchJunction& e : pairs.edges)
      if (e.length >= concave_length && whole(e.a) && whole(e.b) && positive(e.a) != positive(e.b))
        return std::nullopt;
    return cut;
  };

  // A pair that found no cut is not tried again until its segment changes (a cut elsewhere
  // leaves it as it was): `version` counts each segment's cuts, `tried` the version a pair failed at.
  std::vector<std::uint32_t> version(next_group, 0);
  constexpr std::uint32_t kNever = 0xffffffffu;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> tried(pairs.concave.size(), {kNever, 0});
  // Each cut splits a segment in two, so there are fewer cuts than nodes.
  for (std::size_t round = 0; round < g.size(); ++round) {
    bool made = false, split_any = false;
    for (std::size_t k = 0; k < pairs.concave.size(); ++k) {
      const auto [a, b, length] = pairs.concave[k];
      if (group[a] != group[b]) continue;
      if (tried[k].first == group[a] && tried[k].second == version[group[a]]) continue;
      const std::uint32_t segment = group[a];
      std::vector<std::uint32_t> in_segment;
      for (std::uint32_t q = 0; q < group.size(); ++q)
        if (group[q] == segment) in_segment.push_back(q);
      for (const auto& [at, other] : {std::pair{a, b}, std::pair{b, a}}) {
        const std::optional<Plane> face = flat_plane(g, members[at], min_nodes, cfg);
        if (!face) continue;
        Eigen::Vector3d normal;
        const std::optional<Cut> cut = cut_along(at, other, length, *face, normal, in_segment);
        if (!cut) continue;
        for (std::uint32_t q : cut->positive) group[q] = next_group;
        // A split patch's nodes beyond the band become a patch of their own on the positive side.
        for (std::uint32_t q : cut->split) {
          const auto piece = static_cast<std::uint32_t>(patches++);
          std::vector<std::uint32_t> kept_all, kept_members, moved_all, moved_members;
          for (std::uint32_t n : all[q]) {
            const bool up = signed_distance(*face, normal, n) > face->band;
            (up ? moved_all : kept_all).push_back(n);
            if (surface[n]) (up ? moved_members : kept_members).push_back(n);
            if (up) patch[n] = static_cast<std::int32_t>(piece);
          }
          all[q] = std::move(kept_all), members[q] = std::move(kept_members);
          all.push_back(std::move(moved_all)), members.push_back(std::move(moved_members));
          group.push_back(next_group);
        }
        split_any = !cut->split.empty();
        ++version[segment];
        version.push_back(0);
        ++next_group;
        made = true;
        break;
      }
      if (made) break;
      tried[k] = {segment, version[segment]};
    }
    if (!made) break;
    if (split_any) {
      pairs = rejudge(patch);
      tried.assign(pairs.concave.size(), {kNever, 0});
    }
  }
  return group;
}

}  // namespace cloudshape::segment
