#include "segment/structure_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "segment/detail/robust_spread.hpp"

namespace cloudshape::segment {
namespace {

std::uint64_t cell_key(std::int64_t x, std::int64_t y) {
  return (static_cast<std::uint64_t>(x) << 32) ^ (static_cast<std::uint64_t>(y) & 0xFFFFFFFFull);
}

}  // namespace

std::vector<StructureFootprint> structure_footprints(const PointList& points, const NeighbourGraph& graph,
                                                     const std::vector<char>& removed,
                                                     const std::vector<StructurePlane>& planes,
                                                     const config::SegmentConfig& cfg) {
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
  // The noise of the plane's own points: their median absolute distance, scaled to a normal
  // deviation (1.4826); robust to the cells at an object's foot that hold some of its points.
  std::vector<std::vector<double>> distance(planes.size());
  for (std::size_t i = 0; i < graph.node_of_point.size(); ++i) {
    const std::uint32_t n = graph.node_of_point[i];
    if (n == kNoNode || plane_of[n] < 0) continue;
    distance[plane_of[n]].push_back(std::abs(planes[plane_of[n]].plane.signed_distance(points[i])));
  }
  for (std::size_t k = 0; k < planes.size(); ++k) {
    StructureFootprint& f = out[k];
    f.plane = planes[k].plane;
    f.cell = detail::median(spacing[k]);
    f.band = std::max(cfg.contact_noise_sigmas * detail::robust_deviation(distance[k]), cfg.contact_min_band * f.cell);
    geometry::plane_basis(f.plane.normal, f.u, f.v);
  }
  for (std::uint32_t n = 0; n < graph.size(); ++n) {
    if (plane_of[n] < 0) continue;
    StructureFootprint& f = out[plane_of[n]];
    if (!(f.cell > 0.0)) continue;
    f.cells.insert(cell_key(static_cast<std::int64_t>(std::floor(graph.nodes[n].dot(f.u) / f.cell)),
                            static_cast<std::int64_t>(std::floor(graph.nodes[n].dot(f.v) / f.cell))));
  }
  return out;
}

bool on_structure(const std::vector<StructureFootprint>& footprints, const Point& p) {
  for (const StructureFootprint& f : footprints) {
    if (f.cells.empty() || !(std::abs(f.plane.signed_distance(p)) <= f.band)) continue;
    const auto x = static_cast<std::int64_t>(std::floor(p.dot(f.u) / f.cell));
    const auto y = static_cast<std::int64_t>(std::floor(p.dot(f.v) / f.cell));
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        if (f.cells.count(cell_key(x + dx, y + dy))) return true;
  }
  return false;
}

}  // namespace cloudshape::segment
