#include "segment/structure_planes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "geometry/pca.hpp"
#include "geometry/robust_spread.hpp"
#include "segment/detail/key_index.hpp"
#include "segment/structure_band.hpp"
#include "segment/structure_planes_scoring.hpp"

namespace cloudshape::segment {
namespace {

using detail::KeyIndex;

constexpr double kPi = 3.14159265358979323846;

struct PlaneFit {
  geometry::Plane plane;
  std::vector<std::uint32_t> inliers;
};

PlaneFit best_plane(const NeighbourGraph& g, const std::vector<std::uint32_t>& active,
                    const std::vector<std::uint32_t>& seeds, const config::SegmentConfig& cfg, std::mt19937_64& rng,
                    parallel::ThreadPool* pool) {
  const double band = cfg.structure_band;
  const double min_cos = std::cos(cfg.structure_normal_degrees * kPi / 180.0);
  std::vector<std::uint32_t> sample = active;
  constexpr std::size_t kScoreSamples = 3000;
  if (sample.size() > kScoreSamples) {
    std::shuffle(sample.begin(), sample.end(), rng);
    sample.resize(kScoreSamples);
  }
  const ScoredNodes scored(g, sample, band);
  std::uniform_int_distribution<std::size_t> pick(0, seeds.size() - 1);
  // Every hypothesis' seed drawn first, in order from the one generator; then the scoring in
  // blocks (any thread count), and the best taken in hypothesis order: the serial answer.
  const std::size_t hypotheses = static_cast<std::size_t>(std::max<std::int64_t>(0, cfg.structure_hypotheses));
  // A seed drawn again is the same plane: only its first draw is scored. A later draw could only
  // tie with it, and ties go to the earlier hypothesis, so the best is the same. A noisy solid
  // has few flat nodes to seed from, and draws most of them many times.
  std::vector<char> seen(g.size(), 0);
  std::vector<geometry::Plane> planes;
  for (std::size_t h = 0; h < hypotheses; ++h) {
    const std::uint32_t seed = seeds[pick(rng)];
    if (seen[seed]) continue;
    seen[seed] = 1;
    geometry::Plane p;
    p.normal = g.normals[seed];
    p.offset = -p.normal.dot(g.nodes[seed]);
    planes.push_back(p);
  }
  // A hypothesis only wins with more inliers than every one before it: its count stops once it
  // cannot beat the best earlier one known (the first block's, then its own block's), and the
  // first best stays the same for any thread count.
  constexpr std::size_t kHypothesesPerBlock = 8;
  const std::size_t distinct = planes.size();
  std::vector<std::size_t> scores(distinct, 0);
  const auto score_block = [&](std::size_t begin, std::size_t end, std::size_t known) {
    for (std::size_t h = begin; h < end; ++h) {
      scores[h] = count_plane_inliers(scored, planes[h], min_cos, known);
      known = std::max(known, scores[h]);  // a count stopped early is no more than `known`
    }
  };
  const std::size_t first = std::min(distinct, kHypothesesPerBlock);
  score_block(0, first, 0);
  const std::size_t first_best = first == 0 ? 0 : *std::max_element(scores.begin(), scores.begin() + first);
  parallel::for_blocks(pool, distinct - first, kHypothesesPerBlock, [&](std::size_t begin, std::size_t end) {
    score_block(first + begin, first + end, first_best);
  });
  geometry::Plane best;
  std::size_t best_score = 0;
  for (std::size_t h = 0; h < distinct; ++h) {
    if (scores[h] > best_score) {
      best_score = scores[h];
      best = planes[h];
    }
  }
  PlaneFit fit;
  fit.plane = best;
  for (int refit = 0; refit < 2; ++refit) {
    fit.inliers = largest_connected(g, band_nodes(g, active, fit.plane, band, min_cos));
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
  const double quotient = coordinate / cell;
  // Within the limits, the floor as the truncation, one lower below a negative fraction: the same
  // integer (a truncated quotient is exact as a double again), in fewer instructions than floor.
  if (quotient > -kLimit && quotient < kLimit) {
    const auto truncated = static_cast<std::int64_t>(quotient);
    return truncated - (static_cast<double>(truncated) > quotient ? 1 : 0);
  }
  const double index = std::floor(quotient);
  return static_cast<std::int64_t>(std::isnan(index) ? 0.0 : std::clamp(index, -kLimit, kLimit));
}

// Cells of the plane's own 2-D frame occupied by the given nodes' projections.
std::size_t occupied_cells(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes,
                           const geometry::Plane& p, double cell) {
  Eigen::Vector3d u, v;
  geometry::plane_basis(p.normal, u, v);
  KeyIndex cells(nodes.size());
  bool added = false;
  // Consecutive nodes (neighbours along a row or a search's path) often share a cell: it is
  // looked up once.
  std::uint64_t previous = 0;
  bool first = true;
  for (std::uint32_t n : nodes) {
    const std::int64_t cu = cell_index(u.dot(g.nodes[n]), cell);
    const std::int64_t cv = cell_index(v.dot(g.nodes[n]), cell);
    const std::uint64_t key = (static_cast<std::uint64_t>(cu) << 32) ^ static_cast<std::uint64_t>(cv & 0xffffffff);
    if (!first && key == previous) continue;
    cells.index(key, added);
    previous = key;
    first = false;
  }
  return cells.size();
}

// Where a contact node's surface meets the plane: from the node down its own surface's steepest
// slope to the plane. A side that leans over the plane (a cone's side over its own base) meets
// it at the plane's edge although its nodes lie above the plane's inside; a wall-like side meets
// it straight below. None for a node whose surface is nearly parallel to the plane.
std::optional<Point> foot_on_plane(const NeighbourGraph& g, std::uint32_t n, const geometry::Plane& p,
                                   double min_slope) {
  const Eigen::Vector3d& s = g.normals[n];
  const Eigen::Vector3d downhill = -(p.normal - p.normal.dot(s) * s);
  const double slope = downhill.norm();  // sine of the angle between the surface and the plane
  if (slope < min_slope) return std::nullopt;
  return Point(g.nodes[n] + (p.signed_distance(g.nodes[n]) / (slope * slope)) * downhill);
}

// How many of the `contact` nodes (what stands on the plane, near it) meet it inside: where their
// surface meets the plane (foot_on_plane) has plane cells beyond it, at least `margin` cells
// away, in all four in-plane directions. A table surrounds what stands on it (also beyond the
// shadow an object casts), while a solid's other faces rise from its face's own edges.
std::size_t standing_inside(const NeighbourGraph& g, const std::vector<std::uint32_t>& inliers,
                            const std::vector<std::uint32_t>& contact, const geometry::Plane& p, double cell,
                            int margin, double min_slope) {
  Eigen::Vector3d u, v;
  geometry::plane_basis(p.normal, u, v);
  const auto cell_of = [&](const Point& x) {
    return std::pair<std::int64_t, std::int64_t>{cell_index(u.dot(x), cell), cell_index(v.dot(x), cell)};
  };
  // Per row (fixed v) and per column (fixed u), the first and last plane cell.
  struct Spans {
    KeyIndex index;
    std::vector<std::pair<std::int64_t, std::int64_t>> span;
    void widen(std::int64_t key, std::int64_t value) {
      bool added = false;
      const std::uint32_t i = index.index(static_cast<std::uint64_t>(key), added);
      if (added) {
        span.emplace_back(value, value);
      } else {
        span[i].first = std::min(span[i].first, value);
        span[i].second = std::max(span[i].second, value);
      }
    }
    const std::pair<std::int64_t, std::int64_t>* find(std::int64_t key) const {
      const std::uint32_t i = index.find(static_cast<std::uint64_t>(key));
      return i == KeyIndex::kAbsent ? nullptr : &span[i];
    }
  };
  Spans rows{KeyIndex(inliers.size()), {}}, cols{KeyIndex(inliers.size()), {}};
  // A cell as the node before's widens nothing more (see occupied_cells).
  std::pair<std::int64_t, std::int64_t> previous{};
  bool first = true;
  for (std::uint32_t n : inliers) {
    const auto cell_uv = cell_of(g.nodes[n]);
    if (!first && cell_uv == previous) continue;
    rows.widen(cell_uv.second, cell_uv.first);
    cols.widen(cell_uv.first, cell_uv.second);
    previous = cell_uv;
    first = false;
  }
  std::size_t inside = 0;
  for (std::uint32_t n : contact) {
    const std::optional<Point> foot = foot_on_plane(g, n, p, min_slope);
    if (!foot) continue;
    const auto [cu, cv] = cell_of(*foot);
    const auto* r = rows.find(cv);
    const auto* c = cols.find(cu);
    if (r == nullptr || c == nullptr) continue;
    if (r->first <= cu - margin && r->second >= cu + margin && c->first <= cv - margin && c->second >= cv + margin) {
      ++inside;
    }
  }
  return inside;
}

double median_spacing(const NeighbourGraph& g, const std::vector<std::uint32_t>& nodes) {
  std::vector<double> s;
  s.reserve(nodes.size());
  for (std::uint32_t n : nodes) s.push_back(g.spacing[n]);
  return geometry::median(std::move(s));
}

// The plane's nodes' spread about it, robustly (detail::robust_deviation of their distances).
double node_deviation(const NeighbourGraph& g, const PlaneFit& fit) {
  std::vector<double> distance;
  distance.reserve(fit.inliers.size());
  for (std::uint32_t n : fit.inliers) distance.push_back(std::abs(fit.plane.signed_distance(g.nodes[n])));
  return geometry::robust_deviation(std::move(distance));
}

// A wall or ground seen from inside the scene (a lidar among them): nearly all else lies on the
// sensor's side of it, and it spans a large share of the scene. A solid's face has its own solid
// behind it; a table's edge, the floor beyond it.
bool encloses_viewer(const NeighbourGraph& g, const std::vector<std::uint32_t>& active, const std::vector<char>& inlier,
                     const PlaneFit& fit, const config::SegmentConfig& cfg) {
  std::size_t front = 0, others = 0;
  for (std::uint32_t n : active) {
    if (inlier[n]) continue;
    ++others;
    front += fit.plane.signed_distance(g.nodes[n]) > 0.0 ? 1 : 0;
  }
  if (others == 0 || static_cast<double>(front) < cfg.structure_enclosing * static_cast<double>(others)) return false;
  const geometry::Pca plane = geometry::compute_pca(g.nodes, fit.inliers);
  const geometry::Pca scene = geometry::compute_pca(g.nodes, active);
  return std::sqrt(std::max(0.0, plane.eigenvalues(2))) >=
         cfg.structure_span * std::sqrt(std::max(0.0, scene.eigenvalues(2)));
}

// How far the surface joined to a plane reaches behind it (its closed side): the 90th percentile
// of the depths behind the band of the nodes reached from its inliers through nodes not in front
// of its band. A solid's face has its solid's other faces going back from its edges as far as the
// solid is deep; a table's edge reaches back its thickness, a wall nothing (the objects in front
// of them are not followed beyond the band). The search starts from the nodes off the plane that
// border it (fewer than its inliers, whose neighbours are mostly inliers too).
double depth_behind(const NeighbourGraph& g, const std::vector<char>& removed,
                    const std::vector<char>& inlier, const std::vector<std::uint32_t>& active,
                    const geometry::Plane& p, double band) {
  std::vector<char> seen(g.size(), 0);
  std::vector<std::uint32_t> queue;
  std::vector<double> depth;
  const auto reach = [&](std::uint32_t m) {
    seen[m] = 1;
    const double height = p.signed_distance(g.nodes[m]);
    if (height > band * g.spacing[m]) return;
    queue.push_back(m);
    if (height < -band * g.spacing[m]) depth.push_back(-height);
  };
  for (std::uint32_t n : active) {
    if (inlier[n]) continue;
    bool borders = false;
    g.for_neighbours(n, [&](std::uint32_t m) { borders = borders || inlier[m] != 0; });
    if (borders) reach(n);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    g.for_neighbours(queue[head], [&](std::uint32_t m) {
      if (!seen[m] && !removed[m] && !inlier[m]) reach(m);
    });
  }
  if (depth.empty()) return 0.0;
  const auto at =
      depth.begin() + static_cast<std::ptrdiff_t>(0.9 * static_cast<double>(depth.size() - 1));
  std::nth_element(depth.begin(), at, depth.end());
  return *at;
}

// The narrower in-plane extent of a plane's inliers: the width of an even rectangle of their
// spread (a strided sample of at most kExtentSamples of them: an extent, not a fit).
double narrower_extent(const NeighbourGraph& g, const std::vector<std::uint32_t>& inliers) {
  constexpr std::size_t kExtentSamples = 4096;
  const std::size_t step =
      std::max<std::size_t>(1, (inliers.size() + kExtentSamples - 1) / kExtentSamples);
  std::vector<std::uint32_t> sample;
  sample.reserve(inliers.size() / step + 1);
  for (std::size_t i = 0; i < inliers.size(); i += step) sample.push_back(inliers[i]);
  const geometry::Pca extent = geometry::compute_pca(g.nodes, sample);
  return std::sqrt(12.0 * std::max(0.0, extent.eigenvalues(1)));
}

}  // namespace

std::vector<StructurePlane> remove_structure(const NeighbourGraph& g, const config::SegmentConfig& cfg,
                                             std::vector<char>& removed, parallel::ThreadPool* pool,
                                             bool from_inside, bool* reaches) {
  std::vector<StructurePlane> found;
  if (reaches != nullptr) *reaches = false;
  std::mt19937_64 rng(static_cast<std::uint64_t>(cfg.seed));
  std::vector<char> tried(g.size(), 0);  // inliers of a plane that proved to be no structure
  const double min_nodes = cfg.structure_min_share * static_cast<double>(g.size());
  for (std::int64_t attempt = 0; attempt < cfg.structure_max_planes + 2 &&
                                 static_cast<std::int64_t>(found.size()) < cfg.structure_max_planes;
       ++attempt) {
    // A plane that proved to be no structure is left out of the search for the next one, but
    // its nodes still count as standing on the next.
    std::vector<std::uint32_t> active, searched, seeds;
    split_nodes(g, removed, tried, 0.02, active, searched, seeds);
    if (seeds.empty() || static_cast<double>(searched.size()) < min_nodes) break;
    PlaneFit fit = best_plane(g, searched, seeds, cfg, rng, pool);
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
    // What stands on the plane, and where it touches it: the nodes just above its band. The plane's
    // own nodes that its noise lifts off it and tilts out of its band stand on nothing: counted as
    // standing, they would spread the footprint over the plane itself.
    const double lift = g.noisy_pixels ? cfg.contact_noise_sigmas * node_deviation(g, fit) : 0.0;
    std::vector<std::uint32_t> standing, contact;
    nodes_above(g, active, inlier, fit.plane, cfg.structure_band,
                cfg.structure_contact * cfg.structure_band, lift, standing, contact);
    const double cell = 2.0 * median_spacing(g, fit.inliers);
    // Nodes of no spacing (one repeated point) span no area to compare.
    if (!(cell > 0.0)) {
      for (std::uint32_t n : fit.inliers) tried[n] = 1;
      continue;
    }
    const double area = static_cast<double>(occupied_cells(g, fit.inliers, fit.plane, cell));
    const double footprint = static_cast<double>(occupied_cells(g, standing, fit.plane, cell));
    const double ratio = footprint > 0.0 ? area / footprint : 0.0;
    // A plane reaching too little beyond what stands on it supports nothing, whatever stands
    // inside it; and only a frame seen from inside may still make it a wall: so a solid's own face,
    // most of the planes tried, costs no more.
    const bool may_enclose = from_inside && g.viewpoint.has_value();
    if (ratio < cfg.structure_reach && !may_enclose) {
      for (std::uint32_t n : fit.inliers) tried[n] = 1;
      continue;
    }
    if (reaches != nullptr && ratio >= cfg.structure_reach) {
      *reaches = true;
      return found;
    }
    // Every node in the plane's band, its connected part or not: the table beyond an object's shadow
    // is cut off from the part in front of it, and still shows where the table reaches.
    const double min_cos = std::cos(cfg.structure_normal_degrees * kPi / 180.0);
    const std::vector<std::uint32_t> in_band = band_nodes(g, active, fit.plane, cfg.structure_band, min_cos);
    // The inliers and the rest of the band (standing_inside takes them in any order).
    std::vector<std::uint32_t> coplanar = fit.inliers;
    for (std::uint32_t n : in_band) {
      if (!inlier[n]) coplanar.push_back(n);
    }
    const std::size_t inside = standing_inside(g, coplanar, contact, fit.plane, cell, cfg.structure_margin_cells,
                                               std::sin(cfg.structure_contact_min_degrees * kPi / 180.0));
    bool supports = static_cast<std::int64_t>(inside) >= cfg.structure_min_standing &&
                    ratio >= cfg.structure_reach;
    // A solid's face: its other faces go back from its edges as deep as the solid, a table's edge
    // its own thickness, a few percent of the table. Not the first support found, the plane through
    // most nodes that things stand on: a kitchen counter's front goes down as deep as the counter
    // is wide, but what stands on the counter is the scene; a second support with its solid behind
    // it is a face of one of the things on the first.
    if (supports && !found.empty()) {
      supports = depth_behind(g, removed, inlier, active, fit.plane, cfg.structure_band) <=
                 cfg.structure_max_behind * narrower_extent(g, fit.inliers);
    }
    const bool encloses = !supports && may_enclose && encloses_viewer(g, active, inlier, fit, cfg);
    if (!supports && !encloses) {
      for (std::uint32_t n : fit.inliers) tried[n] = 1;
      continue;
    }
    // Seen from inside, everything in a wall's plane is wall: its parts apart (between windows,
    // beyond an occluder's shadow) too, but in the plane, within the noise its connected part shows,
    // not merely within its band: a ball's top, resting on the ground, lies a few coarse voxels
    // of the ground's band high, half a metre above the ground itself.
    if (encloses) {
      const double noise = cfg.contact_noise_sigmas * node_deviation(g, fit);
      fit.inliers.clear();
      for (std::uint32_t n : in_band) {
        const double limit = std::max(noise, cfg.contact_min_band * g.spacing[n]);
        if (inlier[n] || std::abs(fit.plane.signed_distance(g.nodes[n])) <= limit) fit.inliers.push_back(n);
      }
    }
    for (std::uint32_t n : fit.inliers) removed[n] = 1;
    found.push_back({fit.plane, fit.inliers.size()});
  }
  return found;
}

}  // namespace cloudshape::segment
