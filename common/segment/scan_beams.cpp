#include "segment/scan_beams.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace cloudshape::segment {

std::optional<std::int64_t> elevation_bin(const Point& p, double bin_degrees) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  const double horizontal = std::hypot(p.x(), p.y());
  if (!p.allFinite() || (horizontal == 0.0 && p.z() == 0.0)) return std::nullopt;
  return static_cast<std::int64_t>(std::floor(std::atan2(p.z(), horizontal) * kDegrees / bin_degrees));
}

ElevationBins::ElevationBins(double bin_degrees) : bin_degrees_(bin_degrees) {
  if (!(bin_degrees > 0.0) || !(180.0 / bin_degrees <= static_cast<double>(kMaxTabulated))) return;
  // elevation_bin's atan2 lies within +-90 degrees, give or take its roundings: its bins, two of
  // room either side.
  lowest_ = static_cast<std::int64_t>(std::floor(-90.0 / bin_degrees)) - 2;
  const auto highest = static_cast<std::int64_t>(std::ceil(90.0 / bin_degrees)) + 2;
  constexpr double kRadians = 3.14159265358979323846 / 180.0;
  for (std::int64_t b = lowest_; b <= highest; ++b) {
    const double degrees = std::clamp(static_cast<double>(b) * bin_degrees, -90.0, 90.0);
    const double edge = std::sin(degrees * kRadians);
    edges_.push_back(edges_.empty() ? edge : std::max(edge, edges_.back()));
  }
  // Eight cells an edge: a point's cell seldom holds an edge below it, so its search seldom steps,
  // and each step is a branch mispredicted (near the poles the edges crowd in sine: a few steps).
  first_edge_.resize(8 * edges_.size());
  cells_per_unit_ = static_cast<double>(first_edge_.size()) / 2.0;
  max_cell_ = static_cast<double>(first_edge_.size() - 1);
  // The first edge above each cell's start (std::upper_bound's), swept: the starts rise with c.
  std::size_t above = 0;
  for (std::size_t c = 0; c < first_edge_.size(); ++c) {
    const double start = -1.0 + static_cast<double>(c) / cells_per_unit_;
    while (above < edges_.size() && !(start < edges_[above])) ++above;
    first_edge_[c] = static_cast<std::uint32_t>(above == 0 ? 0 : above - 1);
  }
}

std::size_t ElevationBins::count_bins(const Point* first, const Point* last, std::size_t* dense) const {
  const Table table{edges_.data(), edges_.size(), first_edge_.data(), cells_per_unit_, max_cell_};
  const std::int64_t lowest = lowest_;
  const double bin_degrees = bin_degrees_;
  std::size_t used = 0;
  for (const Point* p = first; p != last; ++p) {
    std::int64_t e = edge_in(table, *p);
    if (e < 0) {
      const std::optional<std::int64_t> b = elevation_bin(*p, bin_degrees);
      if (!b) continue;
      e = *b - lowest;
    }
    ++dense[e];
    ++used;
  }
  return used;
}

std::vector<ElevationBeam> elevation_beams(const std::vector<std::pair<std::int64_t, std::size_t>>& sorted_counts) {
  std::vector<ElevationBeam> beams;
  for (std::size_t k = 0; k < sorted_counts.size();) {
    std::size_t end = k + 1, run = sorted_counts[k].second;
    while (end < sorted_counts.size() && sorted_counts[end].first == sorted_counts[end - 1].first + 1) {
      run += sorted_counts[end++].second;
    }
    if (run >= kMinPointsPerBeam) beams.push_back({sorted_counts[k].first, sorted_counts[end - 1].first, run});
    k = end;
  }
  return beams;
}

std::vector<std::int32_t> scan_beam_of_points(const PointList& points, const config::SegmentConfig& cfg) {
  std::vector<std::int32_t> beam_of(points.size(), -1);
  const double bin = cfg.scan_elevation_bin_degrees;
  if (!(bin > 0.0)) return beam_of;
  const ElevationBins bins(bin);
  std::vector<std::optional<std::int64_t>> bin_of(points.size());
  std::map<std::int64_t, std::size_t> counts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bin_of[i] = bins(points[i]);
    if (bin_of[i]) ++counts[*bin_of[i]];
  }
  const std::vector<ElevationBeam> beams =
      elevation_beams(std::vector<std::pair<std::int64_t, std::size_t>>(counts.begin(), counts.end()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!bin_of[i]) continue;
    const auto beam = std::lower_bound(beams.begin(), beams.end(), *bin_of[i],
                                       [](const ElevationBeam& b, std::int64_t v) { return b.last_bin < v; });
    if (beam != beams.end() && beam->first_bin <= *bin_of[i]) beam_of[i] = static_cast<std::int32_t>(beam - beams.begin());
  }
  return beam_of;
}

std::size_t beams_spanned(const std::vector<std::int32_t>& beam_of, const std::vector<std::uint32_t>& indices) {
  std::set<std::int32_t> beams;
  for (std::uint32_t i : indices) {
    if (i < beam_of.size() && beam_of[i] >= 0) beams.insert(beam_of[i]);
  }
  return beams.size();
}

}  // namespace cloudshape::segment
