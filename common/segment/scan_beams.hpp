// Which beam of a multi-beam lidar frame (in its sensor's frame) each point lies on, and how many
// beams a set of points spans: an object seen on too few scan lines shows no vertical extent.
#pragma once

#include <algorithm>
#include <cmath>
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

  std::optional<std::int64_t> operator()(const Point& p) const {
    const std::int64_t e = edge_index(p);
    if (e >= 0) return lowest_ + e;
    return elevation_bin(p, bin_degrees_);
  }

  // The bin of `p` less lowest() when the table decides it; -1 when elevation_bin must (not
  // tabulated, within kEdgeMargin of an edge, squares that over- or underflow). Inline: a lidar
  // test bins every point of a cloud.
  std::int64_t edge_index(const Point& p) const {
    if (edges_.empty()) return -1;
    return edge_in(Table{edges_.data(), edges_.size(), first_edge_.data(), cells_per_unit_, max_cell_}, p);
  }

  // Adds one to dense[b - lowest()] for the bin b of each point of [first, last) that has one
  // (tabulated() only: dense holds span() counts); returns how many had one. operator()'s bins.
  std::size_t count_bins(const Point* first, const Point* last, std::size_t* dense) const;

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
  double max_cell_ = 0.0;  // the last cell of first_edge_

  // The members edge_in reads, copied: a loop keeps them in registers across its elevation_bin calls.
  struct Table {
    const double* edges;
    std::size_t size;
    const std::uint32_t* first_edge;
    double cells_per_unit, max_cell;
  };
  static std::int64_t edge_in(const Table& t, const Point& p) {
    // s = sin(elevation), off by a few roundings (1e-15) while the squares neither over- nor
    // underflow; atan2's bin is off by as little. So a sine farther than kEdgeMargin from every
    // edge's lies in atan2's bin (|d sin| <= |d angle|: the margin in angle is larger still).
    const double r2 = p.x() * p.x() + p.y() * p.y() + p.z() * p.z();
    if (!(r2 >= 1e-280 && r2 <= 1e280)) return -1;
    const double s = p.z() / std::sqrt(r2);
    const double cell = std::clamp((s + 1.0) * t.cells_per_unit, 0.0, t.max_cell);
    std::size_t e = t.first_edge[static_cast<std::size_t>(cell)];
    while (e > 0 && t.edges[e] > s) --e;
    while (e + 1 < t.size && t.edges[e + 1] <= s) ++e;
    if (e + 1 >= t.size || !(s - t.edges[e] > kEdgeMargin) || !(t.edges[e + 1] - s > kEdgeMargin)) return -1;
    return static_cast<std::int64_t>(e);
  }
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
