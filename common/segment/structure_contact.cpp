#include "segment/structure_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry/robust_spread.hpp"

namespace cloudshape::segment {
namespace {

std::uint64_t cell_key(std::int64_t x, std::int64_t y) {
  return (static_cast<std::uint64_t>(x) << 32) ^ (static_cast<std::uint64_t>(y) & 0xFFFFFFFFull);
}

// The in-plane cell of `p` in footprint `f`.
std::uint64_t key_of(const StructureFootprint& f, const Point& p) {
  return cell_key(static_cast<std::int64_t>(std::floor(p.dot(f.u) / f.cell)),
                  static_cast<std::int64_t>(std::floor(p.dot(f.v) / f.cell)));
}

// A flat plane: the cells its nodes lie in, at height 0, and its points' distances from it.
void add_node_cells(const PointList& points, const NeighbourGraph& graph, const std::vector<std::int32_t>& plane_of,
                    std::vector<StructureFootprint>& out, std::vector<std::vector<double>>& distance) {
  std::vector<std::size_t> count(out.size(), 0);
  for (const std::uint32_t n : graph.node_of_point) {
    if (n != kNoNode && plane_of[n] >= 0) ++count[plane_of[n]];
  }
  for (std::size_t k = 0; k < out.size(); ++k) distance[k].reserve(count[k]);
  for (std::size_t i = 0; i < graph.node_of_point.size(); ++i) {
    const std::uint32_t n = graph.node_of_point[i];
    if (n == kNoNode || plane_of[n] < 0) continue;
    distance[plane_of[n]].push_back(std::abs(out[plane_of[n]].plane.signed_distance(points[i])));
  }
  for (std::uint32_t n = 0; n < graph.size(); ++n) {
    if (plane_of[n] < 0 || !(out[plane_of[n]].cell > 0.0)) continue;
    out[plane_of[n]].cells.try_emplace(key_of(out[plane_of[n]], graph.nodes[n]), 0.0);
  }
}

// A plane that need not be flat: the cells its points beside what it left lie in, each at their
// median height over the plane, and the points' distances from their cell's height.
void add_cell_heights(const PointList& points, const NeighbourGraph& graph, const std::vector<char>& removed,
                      const std::vector<std::int32_t>& plane_of, std::vector<StructureFootprint>& out,
                      std::vector<std::vector<double>>& distance) {
  // Only the plane's nodes beside a node it left are read: what the footprints are asked about
  // lies in those (a solid's foot), and a floor's far reaches cost nothing.
  std::vector<char> beside_kept(graph.size(), 0);
  for (std::uint32_t n = 0; n < graph.size(); ++n) {
    if (plane_of[n] < 0) continue;
    graph.for_neighbours(n, [&](std::uint32_t m) { beside_kept[n] |= removed[m] ? 0 : 1; });
  }
  // Each point's cell numbered as first met (one look-up a point), then the heights grouped by
  // cell in one array (a counting sort): a median per cell without a vector per cell.
  constexpr std::uint32_t kNoCell = 0xffffffffu;
  std::vector<detail::KeyIndex> cell_index(out.size());
  std::vector<std::vector<std::uint32_t>> cell_number(out.size());  // per plane: its cells' numbers here
  std::vector<std::pair<std::int32_t, std::uint64_t>> cell_ids;   // plane, in-plane key
  std::vector<std::uint32_t> cell_of(points.size(), kNoCell), cell_begin;
  std::vector<double> height_of(points.size(), 0.0);
  for (std::size_t i = 0; i < graph.node_of_point.size(); ++i) {
    const std::uint32_t n = graph.node_of_point[i];
    if (n == kNoNode || plane_of[n] < 0 || !beside_kept[n] || !(out[plane_of[n]].cell > 0.0)) continue;
    const StructureFootprint& f = out[plane_of[n]];
    const std::uint64_t key = key_of(f, points[i]);
    bool added = false;
    const std::uint32_t local = cell_index[plane_of[n]].index(key, added);
    if (added) {
      cell_number[plane_of[n]].push_back(static_cast<std::uint32_t>(cell_ids.size()));
      cell_ids.emplace_back(plane_of[n], key);
      cell_begin.push_back(0);
    }
    const std::uint32_t cell = cell_number[plane_of[n]][local];
    cell_of[i] = cell;
    ++cell_begin[cell];
    height_of[i] = f.plane.signed_distance(points[i]);
  }
  std::uint32_t total = 0;
  for (std::uint32_t& c : cell_begin) total += std::exchange(c, total);
  cell_begin.push_back(total);
  std::vector<double> heights(total);
  std::vector<std::uint32_t> next(cell_begin.begin(), cell_begin.end() - 1);
  for (std::size_t i = 0; i < cell_of.size(); ++i) {
    if (cell_of[i] != kNoCell) heights[next[cell_of[i]]++] = height_of[i];
  }
  for (std::size_t c = 0; c < cell_ids.size(); ++c) {
    const auto first = heights.begin() + cell_begin[c], last = heights.begin() + cell_begin[c + 1];
    const auto middle = first + (last - first) / 2;  // the upper middle, as detail::median
    std::nth_element(first, middle, last);
    const double height = *middle;
    const auto [k, key] = cell_ids[c];
    out[k].cells.try_emplace(key, height);
    // The median is one of the cell's own heights: its zero deviation left out, or cells of a
    // few points would halve the noise.
    for (auto h = first; h != last; ++h) {
      if (h != middle) distance[k].push_back(std::abs(*h - height));
    }
  }
}

}  // namespace

std::vector<StructureFootprint> structure_footprints(const PointList& points, const NeighbourGraph& graph,
                                                     const std::vector<char>& removed,
                                                     const std::vector<StructurePlane>& planes,
                                                     const config::SegmentConfig& cfg, bool cell_heights) {
  std::vector<StructureFootprint> out(planes.size());
  if (planes.empty()) return out;
  // Each removed node belongs to the plane nearest to it.
  std::vector<std::int32_t> plane_of(graph.size(), -1);
  std::vector<std::vector<double>> spacing(planes.size());
  for (std::uint32_t n = 0; n < graph.size(); ++n) {
    if (!removed[n]) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < planes.size(); ++k) {
      const double d = std::abs(planes[k].plane.signed_distance(graph.nodes[n]));
      if (d < nearest) nearest = d, plane_of[n] = static_cast<std::int32_t>(k);
    }
    spacing[plane_of[n]].push_back(graph.spacing[n]);
  }
  for (std::size_t k = 0; k < planes.size(); ++k) {
    StructureFootprint& f = out[k];
    f.plane = planes[k].plane;
    f.cells = detail::CellValues(spacing[k].size());
    f.cell = geometry::median(std::move(spacing[k]));
    geometry::plane_basis(f.plane.normal, f.u, f.v);
  }
  // The noise of the plane's own points: their median absolute distance (from the plane, or from
  // their cell's height), scaled to a normal deviation (1.4826); robust to the cells at an
  // object's foot that hold some of its points.
  std::vector<std::vector<double>> distance(planes.size());
  if (cell_heights) {
    add_cell_heights(points, graph, removed, plane_of, out, distance);
  } else {
    add_node_cells(points, graph, plane_of, out, distance);
  }
  for (std::size_t k = 0; k < planes.size(); ++k) {
    StructureFootprint& f = out[k];
    f.band = std::max(cfg.contact_noise_sigmas * geometry::robust_deviation(std::move(distance[k])),
                      cfg.contact_min_band * f.cell);
    if (f.cells.empty()) continue;
    f.lowest = std::numeric_limits<double>::infinity();
    f.highest = -std::numeric_limits<double>::infinity();
    for (const double height : f.cells.values()) {
      f.lowest = std::min(f.lowest, height);
      f.highest = std::max(f.highest, height);
    }
  }
  return out;
}

bool on_structure(const std::vector<StructureFootprint>& footprints, const Point& p) {
  for (const StructureFootprint& f : footprints) {
    const double d = f.plane.signed_distance(p);
    if (f.cells.empty() || !(d >= f.lowest - f.band && d <= f.highest + f.band)) continue;
    const auto x = static_cast<std::int64_t>(std::floor(p.dot(f.u) / f.cell));
    const auto y = static_cast<std::int64_t>(std::floor(p.dot(f.v) / f.cell));
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const double* height = f.cells.find(cell_key(x + dx, y + dy));
        if (height != nullptr && std::abs(d - *height) <= f.band) return true;
      }
    }
  }
  return false;
}

}  // namespace cloudshape::segment
