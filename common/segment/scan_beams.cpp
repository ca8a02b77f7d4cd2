#include "segment/scan_beams.hpp"

#include <cmath>
#include <map>
#include <set>

namespace cloudshape::segment {

std::vector<std::int32_t> scan_beam_of_points(const PointList& points, const config::SegmentConfig& cfg) {
  constexpr double kDegrees = 180.0 / 3.14159265358979323846;
  // As scan_origin: a beam holds a ring's worth of returns, fewer in a run are strays.
  constexpr std::size_t kMinPerBeam = 10;
  constexpr std::int64_t kNoBin = INT64_MIN;
  std::vector<std::int32_t> beam_of(points.size(), -1);
  const double bin = cfg.scan_elevation_bin_degrees;
  if (!(bin > 0.0)) return beam_of;
  std::vector<std::int64_t> bin_of(points.size(), kNoBin);
  std::map<std::int64_t, std::size_t> counts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    const double horizontal = std::hypot(p.x(), p.y());
    if (!p.allFinite() || (horizontal == 0.0 && p.z() == 0.0)) continue;
    bin_of[i] = static_cast<std::int64_t>(std::floor(std::atan2(p.z(), horizontal) * kDegrees / bin));
    ++counts[bin_of[i]];
  }
  std::map<std::int64_t, std::int32_t> beam_of_bin;
  std::int32_t beams = 0;
  for (auto it = counts.begin(); it != counts.end();) {
    auto end = std::next(it);
    std::size_t run = it->second;
    while (end != counts.end() && end->first == std::prev(end)->first + 1) run += (end++)->second;
    if (run >= kMinPerBeam) {
      for (auto b = it; b != end; ++b) beam_of_bin[b->first] = beams;
      ++beams;
    }
    it = end;
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (bin_of[i] == kNoBin) continue;
    const auto found = beam_of_bin.find(bin_of[i]);
    if (found != beam_of_bin.end()) beam_of[i] = found->second;
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
