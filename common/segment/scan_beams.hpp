// Which beam of a multi-beam lidar frame (in its sensor's frame) each point lies on, and how many
// beams a set of points spans: an object seen on too few scan lines shows no vertical extent.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "config/stage_configs.hpp"
#include "geometry/point_cloud.hpp"

namespace cloudshape::segment {

// A beam holds a ring's worth of returns; fewer in a run of bins are strays (a sparse cloud leaves
// bins occupied by chance alone).
inline constexpr std::size_t kMinPointsPerBeam = 10;

// The elevation bin (of `bin_degrees`) of `p` seen from the origin; none for the origin itself or
// a non-finite point.
std::optional<std::int64_t> elevation_bin(const Point& p, double bin_degrees);

// elevation_bin of many points, the same bins: the sines of the bins' lower edges tabulated, so
// that a point's bin is found by comparing its z / |p| with them (a square root, no atan2). A
// point within kEdgeMargin of an edge, or one whose squares over- or underflow, is binned by
// elevation_bin itself: the two differ by rounding only, far below that margin. Bins narrower
// than 180 / kMaxTabulated degrees are not tabulated (all points go to elevation_bin).
class ElevationBins {
 public:
  static constexpr double kEdgeMargin = 1e-9;
  static constexpr std::int64_t kMaxTabulated = 1 << 16;

  explicit ElevationBins(double bin_degrees);

  std::optional<std::int64_t> operator()(const Point& p) const;

  // Every bin operator() returns lies in [lowest(), lowest() + span()) when tabulated(): dense
  // counts fit an array of span() entries.
  bool tabulated() const { return !edges_.empty(); }
  std::int64_t lowest() const { return lowest_; }
  std::size_t span() const { return edges_.size(); }

 private:
  double bin_degrees_ = 0.0;
  std::int64_t lowest_ = 0;      // the bin whose lower edge is edges_[0]
  std::vector<double> edges_;    // the sine of bin lowest_ + e's lower edge, clamped to [-1, 1]
  std::vector<std::uint32_t> first_edge_;  // per cell of s (uniform over [-1, 1]): an edge at or below it
  double cells_per_unit_ = 0.0;
};

// A beam: a run of adjacent occupied elevation bins, empty ones either side, holding at least
// kMinPointsPerBeam points.
struct ElevationBeam {
  std::int64_t first_bin = 0, last_bin = 0;
  std::size_t points = 0;
};

// The beams of per-bin point counts sorted by bin, lowest first.
std::vector<ElevationBeam> elevation_beams(const std::vector<std::pair<std::int64_t, std::size_t>>& sorted_counts);

// Per point, the beam it lies on, numbered by elevation from the origin: beams are the runs of
// adjacent occupied bins (cfg.scan_elevation_bin_degrees) holding a ring's worth of points, as
// scan_origin finds them; -1 for a point in no beam (a stray return, the origin itself).
std::vector<std::int32_t> scan_beam_of_points(const PointList& points, const config::SegmentConfig& cfg);

// The distinct beams (beam_of >= 0) of the points `indices` select.
std::size_t beams_spanned(const std::vector<std::int32_t>& beam_of, const std::vector<std::uint32_t>& indices);

}  // namespace cloudshape::segment
