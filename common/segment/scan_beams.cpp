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
  std::vector<std::optional<std::int64_t>> bin_of(points.size());
  std::map<std::int64_t, std::size_t> counts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bin_of[i] = elevation_bin(points[i], bin);
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
