#include "segment/structure_planes.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_set>

#include "geometry/pca.hpp"

namespace cloudshape::segment {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct PlaneFit {
  geometry::Plane plane;
  std::vector<std::uint32_t> inliers;
};

bool is_inlier(const NeighbourGraph& g, std::uint32_t n, const geometry::Plane& p, double band, double min_cos) {
  return std::abs(p.signed_distance(g.nodes[n])) <= band * g.spacing[n] &&
         std::abs(g.normals[n].dot(p.normal)) >= min_cos;
}

// The largest set of inliers connected through graph edges among themselves.
std::vector<std::uint32_t> largest_connected(const NeighbourGraph& g, const std::vector<std::uint32_t>& members) {
  std::vector<int> state(g.size(), 0);  // 0 not a member, 1 member unvisited, 2 visited
  for (std::uint32_t n : members) state[n] = 1;
  std::vector<std::uint32_t> best, current, stack;
  for (std::uint32_t seed : members) {
    if (state[seed] != 1) continue;
    current.clear();
    stack.assign(1, seed);
    state[seed] = 2;
    while (!stack.empty()) {
      const std::uint32_t n = stack.back();
      stack.pop_back();
      current.push_back(n);
      g.for_neighbours(n, [&](std::uint32_t m) {
        if (state[m] == 1) {
          state[m] = 2;
          stack.push_back(m);
        }
      });
    }
    if (current.size() > best.size()) best.swap(current);
  }
  return best;
}

PlaneFit best_plane(const NeighbourGraph& g, const std::vector<std::uint32_t>& active,
                    const std::vector<std::uint32_t>& seeds, const config::SegmentConfig& cfg, std::mt19937_64& rng) {
  const double band = cfg.structure_band;
  const double min_cos = std::cos(cfg.structure_normal_degrees * kPi / 180.0);
  std::vector<std::uint32_t> sample = active;
  constexpr std::size_t kScoreSamples = 3000;
  if (sample.size() > kScoreSamples) {
    std::shuffle(sample.begin(), sample.end(), rng);
    sample.resize(kScoreSamples);
  }
  std::uniform_int_distribution<std::size_t> pick(0, seeds.size() - 1);
  geometry::Plane best;
  std::size_t best_score = 0;
  for (std::int64_t h = 0; h < cfg.structure_hypotheses; ++h) {
    const std::uint32_t s = seeds[pick(rng)];
    geometry::Plane p;
    p.normal = g.normals[s];
    p.offset = -p.normal.dot(g.nodes[s]);
    std::size_t score = 0;
    for (std::uint32_t n : sample) score += is_inlier(g, n, p, band, min_cos) ? 1 : 0;
    if (score > best_score) {
      best_score = score;
      best = p;
    }
  }
  PlaneFit fit;
  fit.plane = best;
  for (int refit = 0; refit < 2; ++refit) {
    fit.inliers.clear();
    for (std::uint32_t n : active) {
      if (is_inlier(g, n, fit.plane, band, min_cos)) fit.inliers.push_back(n);
    }
    fit.inliers = largest_connected(g, fit.inliers);
    if (fit.inliers.size() < 3) break;
    const geometry::Pca pca = geometry::compute_pca(g.nodes, fit.inliers);
    geometry::Plane refined;
    refined.normal = pca.eigenvectors.col(0).normalized();
    if (refined.normal.dot(fit.plane.normal) < 0.0) refined.normal = -refined.normal;
    refined.offset = -refined.normal.dot(pca.centroid);
    fit.plane = refined;
  }
  return fit;
}

// The cell of an in-plane coordinate; clamped, since a node spacing near zero makes the quotient
// overflow any integer (found by fuzzing PointCloud2 input: a cast of infinity is undefined).
std::int64_t cell_index(double coordinate, double cell) {
  constexpr double kLimit = 4.0e18;
  const double index = std::floor(coordinate / cell);
  return static_cast<std::int64_t>(std::isnan(index) ? 0.0 : std::clamp(index, -kLimit, kLimit));
}

// Cells of the plane's own 2-D frame occupied by the given nodes' projections.
std::size_t occupied_cells(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes,
                           const geometry::Plane& p, double cell) {
  Eigen::Vector3d u, v;
  geometry::plane_basis(p.normal, u, v);
  std::unordered_set<std::uint64_t> cells;
  for (std::uint32_t n : nodes) {
    const std::int64_t cu = cell_index(u.dot(g.nodes[n]), cell);
    const std::int64_t cv = cell_index(v.dot(g.nodes[n]), cell);
    cells.insert((static_cast<std::uint64_t>(cu) << 32) ^ static_cast<std::uint64_t>(cv & 0xffffffff));
  }
  return cells.size();
}

// How many of the `contact` nodes (what stands on the plane, where it meets it) lie inside the
// plane: their projection has plane cells beyond it, at least `margin` cells away, in all four
// in-plane directions. A table surrounds what stands on it (also beyond the shadow an object
// casts), while a solid's other faces rise from its face's own edges, where the face ends.
std::size_t standing_inside(const NeighbourGraph& g, const std::vector<std::uint32_t>& inliers,
                            const std::vector<std::uint32_t>& contact, const geometry::Plane& p, double cell,
                            int margin) {
  Eigen::Vector3d u, v;
  geometry::plane_basis(p.normal, u, v);
  const auto cell_of = [&](std::uint32_t n) {
    return std::pair<std::int64_t, std::int64_t>{cell_index(u.dot(g.nodes[n]), cell), cell_index(v.dot(g.nodes[n]), cell)};
  };
  // Per row (fixed v) and per column (fixed u), the first and last plane cell.
  std::unordered_map<std::int64_t, std::pair<std::int64_t, std::int64_t>> rows, cols;
  const auto widen = [](auto& map, std::int64_t key, std::int64_t value) {
    auto [it, added] = map.emplace(key, std::pair{value, value});
    if (!added) {
      it->second.first = std::min(it->second.first, value);
      it->second.second = std::max(it->second.second, value);
    }
  };
  for (std::uint32_t n : inliers) {
    const auto [cu, cv] = cell_of(n);
    widen(rows, cv, cu);
    widen(cols, cu, cv);
  }
  std::size_t inside = 0;
  for (std::uint32_t n : contact) {
    const auto [cu, cv] = cell_of(n);
    const auto r = rows.find(cv);
    const auto c = cols.find(cu);
    if (r == rows.end() || c == cols.end()) continue;
    if (r->second.first <= cu - margin && r->second.second >= cu + margin && c->second.first <= cv - margin &&
        c->second.second >= cv + margin) {
      ++inside;
    }
  }
  return inside;
}

double median_spacing(const NeighbourGraph& g, std::vector<std::uint32_t> nodes) {
  if (nodes.empty()) return 0.0;
  std::vector<double> s;
  s.reserve(nodes.size());
  for (std::uint32_t n : nodes) s.push_back(g.spacing[n]);
  std::nth_element(s.begin(), s.begin() + s.size() / 2, s.end());
  return s[s.size() / 2];
}

}  // namespace

std::vector<StructurePlane> remove_structure(const NeighbourGraph& g, const config::SegmentConfig& cfg,
                                             std::vector<char>& removed) {
  std::vector<StructurePlane> found;
  std::mt19937_64 rng(static_cast<std::uint64_t>(cfg.seed));
  std::vector<char> tried(g.size(), 0);  // inliers of a plane that proved to be no structure
  const double min_nodes = cfg.structure_min_share * static_cast<double>(g.size());
  for (std::int64_t attempt = 0; attempt < cfg.structure_max_planes + 2 &&
                                 static_cast<std::int64_t>(found.size()) < cfg.structure_max_planes;
       ++attempt) {
    // A plane that proved to be no structure is left out of the search for the next one, but
    // its nodes still count as standing on the next.
    std::vector<std::uint32_t> active, searched, seeds;
    for (std::uint32_t n = 0; n < g.size(); ++n) {
      if (removed[n]) continue;
      active.push_back(n);
      if (tried[n]) continue;
      searched.push_back(n);
      if (g.curvature[n] < 0.02) seeds.push_back(n);
    }
    if (seeds.empty() || static_cast<double>(searched.size()) < min_nodes) break;
    PlaneFit fit = best_plane(g, searched, seeds, cfg, rng);
    if (static_cast<double>(fit.inliers.size()) < min_nodes) break;

    std::vector<char> inlier(g.size(), 0);
    for (std::uint32_t n : fit.inliers) inlier[n] = 1;
    // The open side: where the sensor is, else where most of the rest lies.
    double side = 0.0;
    if (g.viewpoint) {
      side = fit.plane.signed_distance(*g.viewpoint) >= 0.0 ? 1.0 : -1.0;
    } else {
      std::ptrdiff_t balance = 0;
      for (std::uint32_t n : active) {
        if (!inlier[n]) balance += fit.plane.signed_distance(g.nodes[n]) > 0.0 ? 1 : -1;
      }
      side = balance >= 0 ? 1.0 : -1.0;
    }
    if (side < 0.0) {
      fit.plane.normal = -fit.plane.normal;
      fit.plane.offset = -fit.plane.offset;
    }
    // What stands on the plane, and where it touches it: the nodes just above its band.
    std::vector<std::uint32_t> standing, contact;
    for (std::uint32_t n : active) {
      const double height = fit.plane.signed_distance(g.nodes[n]) / g.spacing[n];
      if (inlier[n] || height <= 0.0) continue;
      standing.push_back(n);
      if (height > cfg.structure_band && height <= cfg.structure_contact * cfg.structure_band) contact.push_back(n);
    }
    const double cell = 2.0 * median_spacing(g, fit.inliers);
    // Nodes of no spacing (one repeated point) span no area to compare.
    if (!(cell > 0.0)) {
      for (std::uint32_t n : fit.inliers) tried[n] = 1;
      continue;
    }
    const double area = static_cast<double>(occupied_cells(g, fit.inliers, fit.plane, cell));
    const double footprint = static_cast<double>(occupied_cells(g, standing, fit.plane, cell));
    const double ratio = footprint > 0.0 ? area / footprint : 0.0;
    const std::size_t inside = standing_inside(g, fit.inliers, contact, fit.plane, cell, cfg.structure_margin_cells);
    const bool structure = static_cast<std::int64_t>(inside) >= cfg.structure_min_standing && ratio >= cfg.structure_reach;
    if (!structure) {
      for (std::uint32_t n : fit.inliers) tried[n] = 1;
      continue;
    }
    for (std::uint32_t n : fit.inliers) removed[n] = 1;
    found.push_back({fit.plane, fit.inliers.size()});
  }
  return found;
}

}  // namespace cloudshape::segment
